#!/usr/bin/env python3
"""scripts/liftoff-study against the theory of Newmark's method.

    study_time_order.py LIFTOFF LIFTOFF_STUDY

A thick free plate (quarter, 2 x 2 Q1 cells) on bilateral springs under a
central force raised smoothly from zero, sin^2(pi tau / 0.1), is run with
dtau = 4e-3 ... 5e-4. Every frequency of this small mesh is resolved
(omega dtau < 1 at the coarsest step), so the probe history's error is in
the asymptotic range: average acceleration (gamma = 1/2) is second order,
and any gamma != 1/2 first order. The study tool must report observed
orders 2 and 1 within 0.2, with the expectation of the other scheme
failing. A sweep given fine to coarse must be refused without a table.
"""

import csv
import os
import subprocess
import sys
import tempfile

SCENE = """
subsection Plate
  set Thickness ratio = 0.2
end
subsection Foundation
  set Model     = bilateral
  set Stiffness = 100
end
subsection Discretization
  set Symmetry      = quarter
  set Cells along x = 2
  set Cells along y = 2
end
subsection Loads
  subsection Point load 1
    set Magnitude    = 1
    set Time history = sin(pi*tau/0.1)^2
  end
end
subsection Time integration
  set End time = 0.1
end
subsection Output
  set Probe points   = 0.25, 0
  set Write energies = false
end
"""
PROBE = "w(0.25;0)"
STEPS = "4e-3,2e-3,1e-3,5e-4"

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402


def study(liftoff, tool, work, name, extra):
    """Run the study; the rows of its study.csv."""
    output = os.path.join(work, name)
    # The tool runs by its shebang (Debian's python3, with numpy and
    # pandas), as a user runs it.
    run = subprocess.run([tool, os.path.join(work, "s.prm"),
                          "--executable", liftoff, "--time-steps", STEPS,
                          "--qoi", PROBE, "--no-plot", "--output", output,
                          "--jobs", "2"]
                         + extra, capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout + run.stderr)
        return None
    # The plan up front, then "k of N" for every run, with the time so far.
    lines = run.stdout.splitlines()
    check(lines[0].startswith("liftoff-study: 4 runs (4 time steps); 2 at "
                              "a time (--jobs 2, 1 rank per run)")
          and all(any(line.startswith("[%d of 4] " % k) and "elapsed" in line
                      for line in lines) for k in range(1, 5)),
          "%s: the plan, then runs 1 to 4 of 4 with the time so far"
          % name)
    with open(os.path.join(output, "study.csv")) as f:
        return list(csv.DictReader(f))


def main():
    liftoff, tool = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "s.prm"), "w") as f:
            f.write(SCENE)
        for name, extra, theory, other in [
                ("gamma-0.5", [], 2.0, 1.0),
                ("gamma-0.6", ["--set", "Time integration/Gamma=0.6"], 1.0,
                 2.0)]:
            rows = study(liftoff, tool, work, name, extra)
            check(rows is not None and len(rows) == 4,
                  "%s: the study ran 4 scenes" % name)
            if not rows:
                continue
            orders = [float(r["order_dtau:" + PROBE]) for r in rows[2:]]
            errors = [float(r["error:" + PROBE]) for r in rows]
            for dt, k in zip(["1e-3", "5e-4"], orders):
                check(abs(k - theory) <= 0.2,
                      "%s: observed dtau order at dtau = %s is %.3f, theory "
                      "%g +- 0.2" % (name, dt, k, theory))
            # The same figure must fail the other scheme's expectation, or
            # the check above could not tell the two schemes apart.
            check(abs(orders[-1] - other) > 0.2,
                  "%s: order %.3f is not %g +- 0.2 (the other scheme)"
                  % (name, orders[-1], other))
            check(errors[-1] == 0 and all(a > b for a, b in
                                          zip(errors, errors[1:])),
                  "%s: errors against the finest run fall to 0: %s"
                  % (name, ", ".join("%.3g" % e for e in errors)))

        output = os.path.join(work, "refused")
        run = subprocess.run([tool, os.path.join(work, "s.prm"),
                              "--executable", liftoff, "--time-steps",
                              "5e-4,1e-3", "--no-plot", "--output", output],
                             capture_output=True, text=True)
        check(run.returncode != 0 and "--time-steps wants its values coarse "
              "to fine" in run.stderr
              and not os.path.exists(os.path.join(output, "study.csv")),
              "time steps fine to coarse refused (exit %d: %s)"
              % (run.returncode, run.stderr.strip()))
    finish()


if __name__ == "__main__":
    main()
