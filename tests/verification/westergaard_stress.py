#!/usr/bin/env python3
"""Westergaard's interior stress under a circular load (issue 37), in SI:
a slab 10 cm thick (E = 30 GPa, nu = 0.2) on a bilateral bed of
k = 5 MPa/m, 12.6 l wide (l = (D / k)^(1/4) = 0.85 m, so its edges do not
matter), carrying P = 50 kN spread uniformly on a disc of radius a = 0.2 m
at its centre (a >= 1.724 h, so Westergaard's equivalent radius b is a):

    sigma = 3 (1 + nu) P / (2 pi h^2) (ln(l / b) + 0.6159)

at the bottom face under the centre. The test checks that closed form
against the exact infinite Kirchhoff plate, computed here by the Hankel
transform

    M(0) = (1 + nu) / 2 q a int_0^inf xi^2 J1(xi a) D / (D xi^4 + k) dxi,
    w(0) = q a int_0^inf J1(xi a) / (D xi^4 + k) dxi,

(q = P / (pi a^2); integrated between the zeros of J1 with scipy), and
then liftoff's `sigma_xx(0;0) [Pa]` (quarter model, Q2, 48 and 96 cells
along a side) against both:

- Westergaard / exact - 1 within 0.5 % (measured -0.26 %);
- liftoff on 96 cells within 1 % of the exact (0.40 %) and the error
  falling at least 3 times from 48 to 96 cells (4.4);
- sigma_yy = sigma_xx under the centre, and sigma_xx = 6 M_xx / h^2 in
  Pa and N m/m, to 1e-9;
- w(0;0) [m] within 2 % of the Kirchhoff plate's (0.8 %: the Mindlin
  plate's shear deflection adds to it).

    westergaard_stress.py LIFTOFF
"""

import csv
import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy import integrate, special

LIFTOFF = os.path.abspath(sys.argv[1])
E, NU, H, K = 30e9, 0.2, 0.1, 5e6
P, A = 50e3, 0.2
D = E * H**3 / (12 * (1 - NU**2))
ELL = (D / K) ** 0.25
LENGTH = 12.6 * ELL
Q = P / (math.pi * A * A)

failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


def hankel(power):
    """int_0^inf s^power J1(s a / l) / (s^4 + 1) ds, piecewise between the
    zeros of J1 (the integrand decays like s^(power - 4.5))."""
    edges = np.concatenate([[0.0], special.jn_zeros(1, 3000) * ELL / A])
    return sum(integrate.quad(lambda s: s**power * special.j1(s * A / ELL)
                              / (s**4 + 1), lo, hi, limit=200)[0]
               for lo, hi in zip(edges[:-1], edges[1:]))


# xi = s / l turns D xi^4 + k into k (s^4 + 1).
exact_moment = (1 + NU) / 2 * Q * A * hankel(2) * D / (K * ELL**3)
exact_stress = 6 * exact_moment / H**2
exact_w = Q * A * hankel(0) / (K * ELL)
b = A if A >= 1.724 * H else math.sqrt(1.6 * A * A + H * H) - 0.675 * H
westergaard = (3 * (1 + NU) * P / (2 * math.pi * H * H)
               * (math.log(ELL / b) + 0.6159))
print(f"l = {ELL:.4f} m, a / l = {A / ELL:.3f}; exact sigma = "
      f"{exact_stress:.6g} Pa, Westergaard {westergaard:.6g} Pa; exact "
      f"w(0) = {exact_w:.6g} m")
check(abs(westergaard / exact_stress - 1) < 5e-3,
      f"Westergaard / exact infinite plate - 1 = "
      f"{westergaard / exact_stress - 1:.2e}")


def run(cells):
    scene = f"""
subsection Units
  set System = SI
  set Length = {LENGTH!r}
  set Thickness = {H}
  set Young's modulus = {E}
  set Density = 2400
  set Gravity = 0
  set Subgrade modulus = {K}
end
subsection Plate
  set Poisson ratio = {NU}
end
subsection Analysis
  set Type = static
end
subsection Foundation
  set Model = bilateral
end
subsection Discretization
  set Symmetry = quarter
  set Cells along x = {cells}
  set Cells along y = {cells}
  set Polynomial degree = 2
end
subsection Loads
  subsection Patch load 1
    set Magnitude = {Q!r}
    set Shape = disc
    set Size = {2 * A}
  end
end
subsection Output
  set Directory = out{cells}
  set Probe quantities = sigma_xx(0; 0), sigma_yy(0; 0), M_xx(0; 0)
end
"""
    with open(f"scene{cells}.prm", "w") as f:
        f.write(scene)
    subprocess.run([LIFTOFF, "--quiet", f"scene{cells}.prm"], check=True)
    with open(f"out{cells}/history.csv") as f:
        return next(csv.DictReader(f))


with tempfile.TemporaryDirectory() as folder:
    os.chdir(folder)
    coarse, fine = run(48), run(96)

sigma = {n: float(r["sigma_xx(0;0) [Pa]"])
         for n, r in ((48, coarse), (96, fine))}
errors = {n: sigma[n] / exact_stress - 1 for n in sigma}
print(f"liftoff sigma_xx(0;0): 48 cells {sigma[48]:.6g} Pa "
      f"({errors[48]:+.2%}), 96 cells {sigma[96]:.6g} Pa ({errors[96]:+.2%})")
check(abs(errors[96]) < 1e-2,
      f"liftoff / exact - 1 on 96 cells = {errors[96]:.2e}")
check(abs(errors[48]) >= 3 * abs(errors[96]),
      f"the error falls {abs(errors[48] / errors[96]):.2f} times from 48 to "
      "96 cells")
check(abs(sigma[96] / westergaard - 1) < 1e-2,
      f"liftoff / Westergaard - 1 on 96 cells = "
      f"{sigma[96] / westergaard - 1:.2e}")
check(abs(float(fine["sigma_yy(0;0) [Pa]"]) / sigma[96] - 1) < 1e-9,
      "sigma_yy = sigma_xx under the centre of the disc")
moment = float(fine["M_xx(0;0) [N m/m]"])
check(abs(6 * moment / H**2 / sigma[96] - 1) < 1e-9,
      f"sigma_xx [Pa] = 6 M_xx [N m/m] / h^2 (M_xx = {moment:.6g} N m/m)")
w = float(fine["w(0;0) [m]"])
check(abs(w / exact_w - 1) < 2e-2,
      f"w(0;0) = {w:.6g} m, / Kirchhoff's - 1 = {w / exact_w - 1:.2e}")

print(f"{failures} failure(s)")
sys.exit(1 if failures else 0)
