#!/usr/bin/env python3
"""The study tool's peaks against Newmark's discrete solution in closed form.

    study_peak.py LIFTOFF LIFTOFF_STUDY

The rigid bounce of study_target.py: a free plate on a bilateral bed,
Gamma = 100, under a uniform pressure q = 1 from tau = 0 moves as
w = (q / Gamma) (1 - cos 10 tau) on any mesh. Average acceleration keeps
the amplitude and shifts the frequency: from rest its steps are exactly

    w_n = 0.01 (1 - cos(n Omega dtau)),  Omega dtau = 2 atan(10 dtau / 2).

With dtau = T / m (T = pi / 10, the time of the peak; m = 4, 8, 16, 32) and
End time 2 T, the peak over a run's own steps is at n = m, tau = T, with
the value 0.01 (1 + cos delta), delta = pi - 2 m atan(pi / (2 m)) ~
pi^3 / (12 m^2): the peak's error falls as dtau^4, where the history's
(a phase error) falls as dtau^2. A coarsest rung of dtau = 2 T / 5,
whose steps miss T, makes the study's common times miss the peak: a peak
read there instead of at each run's own steps is off by 2 % and fails.
The study must report, for peak:w, each run's peak and its time as in
closed form, its error against the reference's peak, and observed orders
near 4 beside the history's near 2.
"""

import csv
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import pressure, scene_text  # noqa: E402

T = math.pi / 10
# dtau = T / m; 2.5: the coarsest rung, 2 T / 5.
MS = (2.5, 4, 8, 16, 32)
PROBE = "w(0.25;0)"
SCENE = scene_text(
    {"Plate": {"Thickness ratio": 0.1},
     "Foundation": {"Model": "bilateral", "Stiffness": 100},
     "Discretization": {"Symmetry": "quarter", "Polynomial degree": 1,
                        "Cells along x": 2, "Cells along y": 2},
     "Time integration": {"End time": repr(2 * T)},
     "Output": {"Probe points": "0.25, 0", "Write energies": "false"}},
    pressure(1))


def discrete_peak(m):
    """Newmark's peak over its own steps n dtau <= 2 T, dtau = T / m:
    value, time."""
    dtau = T / m
    omega = 2 * math.atan(10 * dtau / 2) / dtau
    return max((0.01 * (1 - math.cos(n * omega * dtau)), n * dtau)
               for n in range(round(2 * m) + 1))


def main():
    liftoff, tool = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        scene = os.path.join(work, "bounce.prm")
        with open(scene, "w") as f:
            f.write(SCENE)
        output = os.path.join(work, "study")
        run = subprocess.run(
            [tool, scene, "--executable", liftoff, "--no-plot",
             "--time-steps", ",".join(repr(T / m) for m in MS),
             "--qoi", PROBE, "--output", output],
            capture_output=True, text=True)
        check(run.returncode == 0, "the study runs (exit %d: %s)"
              % (run.returncode, run.stderr.strip()))
        if run.returncode:
            finish()
        with open(os.path.join(output, "study.csv")) as f:
            rows = list(csv.DictReader(f))
        name = "peak:" + PROBE
        check(all(k + name in rows[0] for k in
                  ("value:", "at:", "error:", "order_dtau:")),
              "study.csv has the peak's value, time, error and order "
              "columns for %s" % name)
        if "value:" + name not in rows[0]:
            finish()
        reference = discrete_peak(MS[-1])[0]
        for m, row in zip(MS, rows):
            value, at = discrete_peak(m)
            got = float(row["value:" + name])
            check(abs(got - value) <= 1e-7 * value
                  and abs(float(row["at:" + name]) - at) <= 1e-9,
                  "dtau = T/%g: peak %.10f at %.6f, closed form %.10f at "
                  "%.6f" % (m, got, float(row["at:" + name]), value, at))
            error = abs(value - reference) / reference
            check(abs(float(row["error:" + name]) - error) <= 1e-7,
                  "dtau = T/%g: peak error %s, closed form %.3e"
                  % (m, row["error:" + name], error))
        for m, row in zip(MS[3:], rows[3:]):
            k_peak = float(row["order_dtau:" + name])
            k_history = float(row["order_dtau:" + PROBE])
            check(abs(k_peak - 4) <= 0.3 and abs(k_history - 2) <= 0.3,
                  "dtau = T/%g: peak order %.2f (theory 4), history order "
                  "%.2f (theory 2)" % (m, k_peak, k_history))
        with open(os.path.join(output, "study.md")) as f:
            md = f.read()
        check("- %s, dtau: " % name in md,
              "study.md estimates the reference's own peak error")
    finish()


if __name__ == "__main__":
    main()
