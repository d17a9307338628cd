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

import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

L, H, E, NU, RHO, K = 5.0, 0.25, 30e9, 0.2, 2400.0, 50e6
D = E * H**3 / (12 * (1 - NU**2))
F0 = D / L
Q = 10e3


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


def resultant(scene):
    """The bed's resultant of every row of history.csv, or None with
    liftoff's message."""
    with tempfile.TemporaryDirectory() as work:
        folder, done = run_scene(LIFTOFF, work, "scene", scene + """
subsection Output
  set Write foundation resultant = true
end
""", ["-q"])
        if done.returncode != 0:
            print(done.stderr.strip())
            return None
        history = read_history(folder)
        key = [k for k in history if k.startswith("resultant")][0]
        return [float(v) for v in history[key]]


def static_si(segment):
    return resultant(UNITS + BED % "" + """
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
    si = resultant(UNITS + BED % "" + MOVING % (
        t0 / 100, t0 * 0.3, Q, -0.4, 0.4, "-1.5 + 100*t; 0.3", -4, 1,
        t0 * 0.1))
    twin = resultant(BED % ("  set Stiffness = %.17g" % gamma) + """
subsection Plate
  set Thickness ratio = %.17g
end
""" % (H / L) + MOVING % (
        0.01, 0.3, Q / (F0 / L), -0.4 / L, 0.4 / L,
        "(-1.5 + 100*(%.17g*tau))/%g; 0.3/%g" % (t0, L, L), -4 / L, 1 / L,
        0.1))
    check(si is not None, "a moving SI line with Profile follows and "
          "Profile start = -4, 0 m (an offset) runs")
    if si is None or twin is None:
        check(False, "the moving line's twin runs")
        return
    dimensionless = [r * F0 for r in twin]
    error = max(abs(a - b) for a, b in zip(si, dimensionless))
    check(len(si) == len(dimensionless) and error < 1e-8 * Q,
          "moving SI line: bed resultant [N] against the twin's x F0 over %d "
          "rows: largest difference %.3g N (largest resultant %.6g N, the "
          "line's load %.6g N)" % (len(si), error, max(si), Q * 0.8))


def main():
    rows = static_si("-0.4, 0, 0.4, 0")
    got = rows[0] if rows else math.nan
    check(abs(got - Q * 0.8) < 1e-6 * Q, "SI static line load: bed resultant "
          "%.6g N, Magnitude x length = %.6g N" % (got, Q * 0.8))

    gamma = K * L**4 / D
    twin = resultant(BED % ("  set Stiffness = %.17g" % gamma) + """
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
    twin_n = twin[0] * F0 if twin else math.nan
    check(abs(twin_n - got) < 1e-9 * Q, "the dimensionless twin's resultant "
          "x F0 = %.6g N, the SI scene's %.6g N" % (twin_n, got))

    rows = static_si("-1, 0, 1, 0")
    got = rows[0] if rows else math.nan
    check(abs(got - Q * 2) < 1e-6 * Q, "Segment = -1, 0, 1, 0 m on a 5 m "
          "plate runs: %.6g N, expected %.6g N" % (got, Q * 2))

    moving(gamma)
    finish()


if __name__ == "__main__":
    main()
