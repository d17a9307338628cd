#!/usr/bin/env python3
"""Moments and deflection of a large thin plate on a bilateral Winkler bed
under a uniform pressure on a small square, against the Kirchhoff solution
of the infinite plate (Hetenyi 1946; Timoshenko and Woinowsky-Krieger,
sec. 57) in Kelvin functions, evaluated here with scipy and not by liftoff.

For a unit point load on an infinite plate (D = 1, bed k = Gamma, radius of
relative stiffness l = Gamma^(-1/4)) at distance r, rho = r / l:

    w    = -(l^2 / (2 pi)) kei(rho)
    M_r  = (1 / (2 pi)) (ker(rho) - (1 - nu) kei'(rho) / rho)
    M_th = (1 / (2 pi)) (nu ker(rho) + (1 - nu) kei'(rho) / rho)

(a positive moment puts the bed-side face in tension, as in liftoff). The
pressure q on the square |x|, |y| <= b is the integral of these over the
square; at the centre the integrand is log-singular and is integrated in
polar coordinates over the eight triangles of the square. The plate is
25 l wide, so its free edges change the answer by about exp(-8.8) relative.

Checks, on 16, 32 and 64 cells along the quarter (Q2, MITC; h = 0.78 l
to 0.20 l):
- w at the centre and at (l, 0), M_xx at the centre and M_xx, M_yy at
  (l, 0), each within 1 % of the closed form on the finest mesh (measured:
  w 1.7e-4 and 2.1e-5, moments 5.1e-3, 3.5e-3, 4.2e-3);
- the moments converge at an order above 1.5 from 32 to 64 cells
  (measured 2.1, 4.0, 2.7), the errors of w do not grow;
- the Green's function itself: the bed carries the whole load, and its
  moments are -(w'' + nu w'/r) of its deflection (finite differences).

    winkler_kelvin.py LIFTOFF
"""

import math
import os
import subprocess
import sys
import tempfile

from scipy import integrate

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from kelvin_square import KelvinSquare  # noqa: E402

LIFTOFF = sys.argv[1]
NU = 0.3
ELL = 0.04
GAMMA = ELL ** -4
B = 0.03125
KELVIN = KelvinSquare(ELL, NU, B)
Q = KELVIN.q  # a unit force on the square
green, at_centre, at_point = KELVIN.green, KELVIN.at_centre, KELVIN.at_point

failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


def scene(cells, folder):
    return f"""
subsection Analysis
  set Type = static
end
subsection Plate
  set Thickness ratio = 0.001
  set Poisson ratio = {NU}
end
subsection Foundation
  set Model = bilateral
  set Stiffness = {GAMMA}
end
subsection Discretization
  set Symmetry = quarter
  set Cells along x = {cells}
  set Cells along y = {cells}
  set Polynomial degree = 2
end
subsection Loads
  subsection Pressure 1
    set Magnitude = {Q}
    set Region = {-B}, {B}, {-B}, {B}
  end
end
subsection Output
  set Directory = {folder}
  set VTU interval = 0
  set Write energies = false
  set Probe points = 0, 0; {ELL}, 0
  set Probe quantities = M_xx(0; 0), M_xx({ELL}; 0), M_yy({ELL}; 0)
end
"""


def run(cells, work):
    folder = os.path.join(work, f"out{cells}")
    prm = os.path.join(work, f"kelvin{cells}.prm")
    with open(prm, "w") as f:
        f.write(scene(cells, folder))
    subprocess.run([LIFTOFF, prm], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(folder, "history.csv")) as f:
        header = f.readline().strip().split(",")
        row = [float(v) for v in f.readline().split(",")]
    return dict(zip(header, row))


reference = {
    "w(0;0)": at_centre(0),
    f"w({ELL};0)": at_point(ELL, 0, 0),
    "M_xx(0;0)": at_centre(1),
    f"M_xx({ELL};0)": at_point(ELL, 0, 1),
    f"M_yy({ELL};0)": at_point(ELL, 0, 2),
}
# The Green's function checked on its own: the bed carries the whole load,
# int Gamma w 2 pi r dr = 1, and its moments are -(w'' + nu w' / r) by finite
# differences of w.
carried, _ = integrate.quad(
    lambda r: GAMMA * green(r, 0)[0] * 2 * math.pi * r, 1e-12, 40 * ELL,
    limit=200)
check(abs(carried - 1) < 1e-8, f"closed form: bed reaction {carried:.10f} = 1")
r, h = 0.7 * ELL, 1e-4 * ELL
w = [green(r + k * h, 0)[0] for k in (-1, 0, 1)]
m_r = -((w[2] - 2 * w[1] + w[0]) / h ** 2 + NU * (w[2] - w[0]) / (2 * h * r))
check(abs(m_r / green(r, 0)[1] - 1) < 1e-5,
      f"closed form: M_r {green(r, 0)[1]:.8g} = -(w'' + nu w'/r) {m_r:.8g}")

with tempfile.TemporaryDirectory() as work:
    errors = {}
    for cells in (16, 32, 64):
        result = run(cells, work)
        for name, exact in reference.items():
            error = abs(result[name] / exact - 1)
            errors.setdefault(name, []).append(error)
            print(f"{cells:3d} cells: {name:14s} liftoff {result[name]: .6e} "
                  f"closed form {exact: .6e} relative error {error:.2e}")
    for name, (_, coarse, fine) in errors.items():
        check(fine < 0.01, f"{name}: relative error {fine:.2e} < 1 %")
        if name.startswith("M"):
            order = math.log2(coarse / fine)
            check(order > 1.5, f"{name}: observed order {order:.2f} > 1.5 "
                  f"({coarse:.2e} -> {fine:.2e})")
        else:
            check(fine <= coarse * 1.05 + 1e-5,
                  f"{name}: error does not grow under refinement "
                  f"({coarse:.2e} -> {fine:.2e})")

sys.exit(1 if failures else 0)
