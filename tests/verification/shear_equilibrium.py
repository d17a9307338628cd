#!/usr/bin/env python3
"""Vertical equilibrium of a region of the plate, from liftoff's shear
forces: for a closed path around a point load P on a bilateral bed,

    integral of Q . n along the path = R_in - P,

R_in the bed's reaction inside (Gamma w integrated over the enclosed area),
since -div Q + Gamma w = f is the plate's vertical equilibrium. The shear
forces are those of the `Probe quantities` (the MITC assumed strain), the
path is a square |x|, |y| = a through the middle of cells, and both
integrals use Gauss-Legendre rules of scipy on the probes' values; nothing
here uses liftoff's own resultants. With the raw gradient grad w - psi the
mid-cell values of Q would differ; a sign or factor slip in Q fails.

Checks (quarter model, Q2, 16 cells along; Gamma = 100, free edges):
- |integral of Q . n - (R_in - P)| < 1e-3 P (measured 4.4e-5, with
  R_in = 0.379 P), and R_in itself between 0
  and P (the path does not hold the whole bed reaction), so the check
  weighs both terms.

Probes of the mirrored parts: the same probes at (-x, y), (x, -y) and
(-x, -y) from the quarter model, which takes them from the image points
with the reflections' signs, equal those of the full model on the same
mesh (32 x 32 cells), to 1e-6 of the largest value: Q_x odd in x, Q_y odd
in y, M_xy odd in both, M_xx even.

    shear_equilibrium.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from scenes import read_history, run_scene_or_fail  # noqa: E402

LIFTOFF = sys.argv[1]
GAMMA, P = 100.0, 1.0
A = 8.5 / 32  # half the side of the path: the middle of a cell
N = 10  # Gauss points per side and per direction of the area

failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


t, wt = np.polynomial.legendre.leggauss(N)
s = 0.5 * A * (t + 1)  # points on [0, a]
ws = 0.5 * A * wt
# The quarter path: x = a, 0 <= y <= a (normal +x) and y = a (normal +y);
# the square's symmetries give the other three quarters.
shear_probes = [f"Q_x({A}; {y})" for y in s] + [f"Q_y({x}; {A})" for x in s]
w_points = [(x, y) for x in s for y in s]

MIRRORED = [f"{name}({sx * x}; {sy * y})"
            for name in ("Q_x", "Q_y", "M_xy", "M_xx")
            for x, y in ((0.3, 0.1), (0.15, 0.35))
            for sx, sy in ((-1, 1), (1, -1), (-1, -1))]


def scene(symmetry, cells, quantities):
    return f"""
subsection Analysis
  set Type = static
end
subsection Plate
  set Thickness ratio = 0.01
end
subsection Foundation
  set Model = bilateral
  set Stiffness = {GAMMA}
end
subsection Discretization
  set Symmetry = {symmetry}
  set Cells along x = {cells}
  set Cells along y = {cells}
  set Polynomial degree = 2
end
subsection Loads
  subsection Point load 1
    set Magnitude = {P}
  end
end
subsection Output
  set VTU interval = 0
  set Write energies = false
  set Probe points = {"; ".join(f"{x}, {y}" for x, y in w_points)}
  set Probe quantities = {", ".join(quantities)}
end
"""


def run(work, name, text):
    """The history's column names and its first row."""
    history = read_history(run_scene_or_fail(LIFTOFF, work, name, text))
    return list(history), np.array([v[0] for v in history.values()])

with tempfile.TemporaryDirectory() as work:
    header, row = run(work, "quarter",
                      scene("quarter", 16, shear_probes + MIRRORED))
    full_header, full_row = run(work, "full", scene("full", 32, MIRRORED))



def quantities(header, row):
    """The values of the probe quantities, in the order of the scene."""
    first = next(k for k, c in enumerate(header)
                 if "(" in c and not c.startswith("w("))
    return row[first:]


w_columns = [c for c in header if c.startswith("w(")]
assert len(w_columns) == N * N
w = np.array([row[header.index(c)] for c in w_columns]).reshape(N, N)
q = quantities(header, row)[:2 * N]

flux = 4 * (ws @ q[:N] + ws @ q[N:])
reaction = 4 * GAMMA * (ws @ w @ ws)
print(f"integral of Q.n = {flux:.6f}, R_in - P = {reaction - P:.6f}, "
      f"R_in = {reaction:.6f}")
check(abs(flux - (reaction - P)) < 1e-3 * P,
      f"|Q flux - (R_in - P)| = {abs(flux - (reaction - P)):.2e} < 1e-3 P")
check(0.05 * P < reaction < 0.95 * P,
      f"R_in = {reaction:.4f} is a real share of P")
quarter_values = quantities(header, row)[2 * N:]
full_values = quantities(full_header, full_row)
assert len(quarter_values) == len(full_values) == len(MIRRORED)
difference = np.max(np.abs(quarter_values - full_values))
largest = np.max(np.abs(full_values))
check(difference < 1e-6 * largest,
      f"mirrored probes, quarter vs full model: max difference "
      f"{difference:.2e} of the largest {largest:.3g}")
sys.exit(1 if failures else 0)
