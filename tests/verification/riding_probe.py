#!/usr/bin/env python3
"""Riding probes (Output/Riding probes, issue 33) against fixed probes: a
patch load crosses a plate on a bilateral bed along y = 0.1 at speed 2,
entering from off the plate; at step k its centre is at x_k = -0.7 + 0.1 k,
and fixed probes (`Probe points` for w, `Probe quantities` for M_xx and
Q_y) stand at x = -0.4, -0.3, ..., 0.4 on its path. Checks:
- in every row whose load is at a fixed probe, `w@patch_load_1`,
  `M_xx@patch_load_1` and `Q_y@patch_load_1` equal the fixed probes' w,
  M_xx and Q_y there (to 1e-12 of the column's largest value; the fixed
  w is a PointFunctional, a separate evaluation);
- while the load is off the plate (`patch_load_1_on` = 0) the riding
  columns are 0;
- a riding probe of a vehicle (`w@vehicle_1`, the vehicle's path point,
  which here carries a wheel) equals that of the patch load on the same
  path;
- a name that is no moving load is refused by name.

    riding_probe.py LIFTOFF
"""

import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402

LIFTOFF = sys.argv[1]
XS = [round(-0.4 + 0.1 * k, 1) for k in range(9)]
NAMES = {x: "%g" % x for x in XS}  # as history.csv names them


def scene(folder, riders):
    probes = "; ".join(f"{x}, 0.1" for x in XS)
    quantities = ", ".join(f"{q}({x}; 0.1)" for x in XS for q in ("M_xx", "Q_y"))
    return f"""
subsection Foundation
  set Model = bilateral
  set Stiffness = 1000
end
subsection Discretization
  set Cells along x = 8
  set Cells along y = 8
  set Polynomial degree = 2
end
subsection Loads
  subsection Patch load 1
    set Magnitude = 100
    set Size = 0.1, 0.1
    set Path = -0.7 + 2*tau; 0.1
  end
  subsection Vehicle 1
    set Magnitude = 0.5
    set Path = -0.7 + 2*tau; 0.1
    set Wheels = 0, 0, 1
  end
end
subsection Time integration
  set Time step = 0.05
  set End time = 0.55
end
subsection Output
  set Directory = {folder}
  set VTU interval = 0
  set Probe points = {probes}
  set Probe quantities = {quantities}
  set Riding probes = {riders}
end
"""


def run(work, name, riders):
    folder = os.path.join(work, name)
    with open(folder + ".prm", "w") as f:
        f.write(scene(folder, riders))
    result = subprocess.run([LIFTOFF, folder + ".prm"], capture_output=True,
                            text=True)
    if result.returncode != 0:
        return None, result.stderr + result.stdout
    path = os.path.join(folder, "history.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(header)}, ""


with tempfile.TemporaryDirectory() as work:
    h, _ = run(work, "ok",
               "w@patch_load_1, M_xx@patch_load_1, Q_y@patch_load_1, "
               "w@vehicle_1")
    check(h is not None, "the scene with riding probes runs")
    if h is not None:
        for q in ("w", "M_xx", "Q_y"):
            rider = h[f"{q}@patch_load_1"]
            scale = abs(rider).max()
            worst, seen = 0.0, 0
            for x in XS:
                rows = np.nonzero(abs(h["patch_load_1_x"] - x) < 1e-9)[0]
                for r in rows:
                    worst = max(worst, abs(rider[r] - h[f"{q}({NAMES[x]};0.1)"][r]))
                    seen += 1
            check(seen == len(XS) and worst <= 1e-12 * scale,
                  f"{q}@patch_load_1 = the fixed probe at the load's x in "
                  f"{seen} rows: largest difference {worst:.1e} of "
                  f"{scale:.3e} (<= 1e-12 relative)")
        off = h["patch_load_1_on"] == 0
        check(off.sum() >= 2 and all(abs(h[f"{q}@patch_load_1"][off]).max()
                                     == 0 for q in ("w", "M_xx", "Q_y")),
              f"off the plate ({off.sum()} rows) the riding columns are 0")
        diff = abs(h["w@vehicle_1"] - h["w@patch_load_1"]).max()
        check(diff <= 1e-14 * abs(h["w@patch_load_1"]).max(),
              f"w@vehicle_1 = w@patch_load_1 on the same path ({diff:.1e})")
    _, error = run(work, "bad", "w@patch_load_2")
    check("Output/Riding probes: <w@patch_load_2> names no moving load"
          in error, f"an unknown load is refused by name: {error.strip()}")
finish()
