#!/usr/bin/env python3
"""Run a grid of foundation stiffnesses Gamma and time steps dtau (p = 1 and
2) on a small Example 3 scene and tabulate, per run: whether it completed,
active-set iterations per step (mean, max), factorisations, CG iterations,
the largest |energy balance error| relative to the largest energy or work,
and whether every history value is finite.

    scripts/stability_grid.py ./build/liftoff > doc/stability-grid.md

Each run takes 20 steps; the scene is a free square plate (quarter, 8 x 8
cells) under a suddenly applied central force.
"""

import csv
import math
import os
import subprocess
import sys
import tempfile

GAMMAS = ["1e-2", "1", "1e2", "1e4", "1e6", "1e8"]
STEPS = ["1e-7", "1e-5", "1e-3", "1e-1"]
N_STEPS = 20

SCENE = """
subsection Plate
  set Thickness ratio = 0.05
  set Poisson ratio = 0.1
end
subsection Foundation
  set Stiffness = {gamma}
end
subsection Discretization
  set Symmetry = quarter
  set Cells along x = 8
  set Cells along y = 8
  set Polynomial degree = {degree}
  set Shear integration = full
end
subsection Loads
  subsection Point load 1
    set Magnitude = 1
  end
end
subsection Time integration
  set Time step = {dt}
  set End time = {end}
end
subsection Output
  set Directory = {directory}
  set VTU interval = 0
  set Probe points = 0.15, 0
  set Write energies = true
end
"""


def run(liftoff, gamma, dt, degree):
    with tempfile.TemporaryDirectory() as work:
        directory = os.path.join(work, "out")
        text = SCENE.format(gamma=gamma, dt=dt, degree=degree,
                            end=repr(N_STEPS * float(dt)), directory=directory)
        result = subprocess.run([liftoff, "-"], input=text, text=True,
                                capture_output=True)
        summary = {}
        try:
            with open(os.path.join(directory, "summary.txt")) as f:
                for line in f:
                    key, _, value = line.strip().rpartition(": ")
                    summary[key] = value
            with open(os.path.join(directory, "history.csv")) as f:
                rows = list(csv.DictReader(f))
        except FileNotFoundError:
            rows = []
        values = [float(v) for r in rows for v in r.values()]
        finite = all(math.isfinite(v) for v in values)
        scale = max([abs(float(r[k])) for r in rows
                     for k in ("kinetic", "strain", "foundation", "work")]
                    + [1e-300])
        balance = max([abs(float(r["balance_error"])) for r in rows] + [0])
        status = ("completed" if result.returncode == 0 else
                  "failed: " + result.stderr.strip().splitlines()[-1][:60]
                  if result.stderr.strip() else "failed")
        return {
            "status": status,
            "steps": len(rows) - 1,
            "iter_mean": summary.get("active-set iterations per step, mean",
                                     ""),
            "iter_max": summary.get("active-set iterations per step, max", ""),
            "factorisations": summary.get("factorisations", ""),
            "cg": summary.get("CG iterations", ""),
            "balance": balance / scale,
            "finite": finite,
        }


def main():
    liftoff = os.path.abspath(sys.argv[1])
    print("| p | Gamma | dtau | status | steps | it/step mean | it max | "
          "factorisations | CG iterations | energy balance error | finite |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    n_bad = 0
    for degree in (1, 2):
        for gamma in GAMMAS:
            for dt in STEPS:
                r = run(liftoff, gamma, dt, degree)
                n_bad += (r["status"] != "completed" or not r["finite"])
                print("| %d | %s | %s | %s | %d | %s | %s | %s | %s | %.1e | %s |"
                      % (degree, gamma, dt, r["status"], r["steps"],
                         r["iter_mean"], r["iter_max"], r["factorisations"],
                         r["cg"], r["balance"], "yes" if r["finite"] else
                         "NO"), flush=True)
    print("\n%d of %d runs failed or were not finite." %
          (n_bad, 2 * len(GAMMAS) * len(STEPS)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
