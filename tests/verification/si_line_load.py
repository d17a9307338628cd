#!/usr/bin/env python3
"""A line load in a scene in SI units against its closed form and against
its dimensionless twin converted here by hand (issue 46, finding 1: the
Segment was passed to the solver in metres, read as units of L, so the
line was Units/Length times too long and too strong).

A 5 m slab on a bilateral bed, static: the bed carries the whole load, so
its resultant [N] is Magnitude [N/m] times the segment's length [m].

- Line load 1, Magnitude 10 kN/m on Segment = -0.4, 0, 0.4, 0 [m]:
  resultant 8 000 N (it was 40 000 N, status completed);
- the same slab written dimensionless (Segment / L, Magnitude / (F0 / L),
  F0 = D / L): its resultant times F0 is the same 8 000 N;
- Segment = -1, 0, 1, 0 [m] lies on the 5 m plate and runs (it was refused
  as outside [-1/2, 1/2]): 20 000 N;
- a moving line (Segment as offsets from a Path in m and s), dynamic: its
  bed resultant [N] row by row equal to the hand-converted twin's times
  F0 (it swung up to 5 times the line's load);
- Output/Profile follows with Profile start = -4, 0 [m], an offset from
  the moving load, is accepted as the twin accepts its offsets (it was
  refused as a point off the plate).

    si_line_load.py LIFTOFF
"""

import csv
import math
import os
import subprocess
import sys
import tempfile

LIFTOFF = os.path.abspath(sys.argv[1])

L, H, E, NU, RHO, K = 5.0, 0.25, 30e9, 0.2, 2400.0, 50e6
D = E * H**3 / (12 * (1 - NU**2))
F0 = D / L
Q = 10e3

failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


BED = """
subsection Foundation
  set Model = bilateral
%s
end
subsection Discretization
  set Cells along x = 8
  set Cells along y = 8
  set Polynomial degree = 2
end
subsection Plate
  set Poisson ratio = %g
end
""" % ("%s", NU)

UNITS = """
subsection Units
  set System = SI
  set Length = %g
  set Thickness = %g
  set Young's modulus = %g
  set Density = %g
  set Gravity = 0
  set Subgrade modulus = %g
end
""" % (L, H, E, RHO, K)


def run(scene):
    """history.csv's rows as dicts, or None with liftoff's message."""
    with tempfile.TemporaryDirectory() as work:
        text = scene + "\nsubsection Output\n  set Directory = out\n" \
            "  set Write foundation resultant = true\nend\n"
        done = subprocess.run([LIFTOFF, "-q", "-"], input=text, cwd=work,
                              capture_output=True, text=True)
        if done.returncode != 0:
            print(done.stderr.strip())
            return None
        with open(os.path.join(work, "out", "history.csv")) as f:
            return list(csv.DictReader(f))


def resultant(rows):
    key = [k for k in rows[0] if k.startswith("resultant")][0]
    return [float(r[key]) for r in rows]


def static_si(segment):
    return run(UNITS + BED % "" + """
subsection Analysis
  set Type = static
end
subsection Loads
  subsection Line load 1
    set Magnitude = %g
    set Segment = %s
  end
end
""" % (Q, segment))


MOVING = """
subsection Time integration
  set Time step = %.17g
  set End time = %.17g
end
subsection Loads
  subsection Line load 1
    set Magnitude = %.17g
    set Segment = %.17g, 0, %.17g, 0
    set Path = %s
  end
end
subsection Output
  set Profile follows = line_load_1
  set Profile start = %.17g, 0
  set Profile end = %.17g, 0
  set Profile points = 11
  set Profile times = %.17g
end
"""


def moving(gamma):
    """The moving line of the SI scene against the twin, row by row."""
    t0 = L * L * math.sqrt(RHO * H / D)
    rows = run(UNITS + BED % "" + MOVING % (
        t0 / 100, t0 * 0.3, Q, -0.4, 0.4, "-1.5 + 100*t; 0.3", -4, 1,
        t0 * 0.1))
    twin = run(BED % ("  set Stiffness = %.17g" % gamma) + """
subsection Plate
  set Thickness ratio = %.17g
end
""" % (H / L) + MOVING % (
        0.01, 0.3, Q / (F0 / L), -0.4 / L, 0.4 / L,
        "(-1.5 + 100*(%.17g*tau))/%g; 0.3/%g" % (t0, L, L), -4 / L, 1 / L,
        0.1))
    check(rows is not None, "a moving SI line with Profile follows and "
          "Profile start = -4, 0 m (an offset) runs")
    if rows is None or twin is None:
        check(False, "the moving line's twin runs")
        return
    si = resultant(rows)
    dimensionless = [r * F0 for r in resultant(twin)]
    error = max(abs(a - b) for a, b in zip(si, dimensionless))
    check(len(si) == len(dimensionless) and error < 1e-8 * Q,
          "moving SI line: bed resultant [N] against the twin's x F0 over %d "
          "rows: largest difference %.3g N (largest resultant %.6g N, the "
          "line's load %.6g N)" % (len(si), error, max(si), Q * 0.8))


def main():
    rows = static_si("-0.4, 0, 0.4, 0")
    got = resultant(rows)[0] if rows else math.nan
    check(abs(got - Q * 0.8) < 1e-6 * Q, "SI static line load: bed resultant "
          "%.6g N, Magnitude x length = %.6g N" % (got, Q * 0.8))

    gamma = K * L**4 / D
    twin = run(BED % ("  set Stiffness = %.17g" % gamma) + """
subsection Analysis
  set Type = static
end
subsection Plate
  set Thickness ratio = %.17g
end
subsection Loads
  subsection Line load 1
    set Magnitude = %.17g
    set Segment = %.17g, 0, %.17g, 0
  end
end
""" % (H / L, Q / (F0 / L), -0.4 / L, 0.4 / L))
    twin_n = resultant(twin)[0] * F0 if twin else math.nan
    check(abs(twin_n - got) < 1e-9 * Q, "the dimensionless twin's resultant "
          "x F0 = %.6g N, the SI scene's %.6g N" % (twin_n, got))

    rows = static_si("-1, 0, 1, 0")
    got = resultant(rows)[0] if rows else math.nan
    check(abs(got - Q * 2) < 1e-6 * Q, "Segment = -1, 0, 1, 0 m on a 5 m "
          "plate runs: %.6g N, expected %.6g N" % (got, Q * 2))

    moving(gamma)
    print("%d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
