#!/usr/bin/env python3
"""A hard simply supported disc (radius R = 1/2, Delta = 0.05, nu = 0.3)
under the pressure q = x, no foundation, static: w against the Mindlin
plate's closed form for the cos(theta) harmonic, so that the rotation
along the rim, psi_theta = 0 there, is held by the normal-tangential
constraints (under an axisymmetric load it vanishes by symmetry and soft
and hard support coincide, so circular_plate.py cannot tell them apart).

The closed form (D = 1, shear stiffness S = 6 chi (1 - nu) / Delta^2):
write psi = grad F + curl G. Then div M + Q = 0 and -div Q = q become
Laplace^2 F = q, w = F - Laplace F / S and Laplace G = k^2 G with
k^2 = 2 S / (1 - nu). For q = r cos(theta) the regular solutions are

    F = (A r + B r^3 + r^5 / 192) cos(theta),   G = C I_1(k r) sin(theta),
    w = (A r + B r^3 + r^5 / 192 - (8 B r + r^3 / 8) / S) cos(theta),
    psi_r = (F_r' + G_r / r) cos,  psi_theta = -(F_r / r + G_r') sin,

A, B, C from w = 0, psi_theta = 0 and M_rr = psi_r' + nu (psi_r
+ d psi_theta / d theta) / r = 0 at r = R. Checked in the test against
Kirchhoff's simply supported disc under q0 x / a (Timoshenko and
Woinowsky-Krieger), w = q0 a^4 rho (1 - rho^2) ((7 + nu) - (3 + nu)
rho^2) / (192 (3 + nu) D) cos(theta): at Delta = 1e-4 they must agree to
1e-6 (the shear terms are O(Delta^2): 1.4e-7 measured).

liftoff: Q2 with the MappingQ2, 1 to 4 global refinements, and a mesh
adapted twice from 2 refinements (hanging nodes on the rim). The errors
of w at three probes, relative to the largest |w| of the reference, must
fall at least like h^2 and be below 1e-5 on the finest mesh; the adapted
mesh must have at most half the error of the mesh it started from
(measured 0.39 of it). Soft simple support on
the finest mesh must differ from the reference by more than 100 times
hard support's error.

    hard_supported_disc.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np
from scipy.special import ive

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from scenes import read_history, run_scene_or_fail  # noqa: E402

LIFTOFF = sys.argv[1]
R, NU, CHI, DELTA = 0.5, 0.3, 5.0 / 6.0, 0.05
PROBES = [(0.25, 0.0), (0.1, 0.2), (-0.3, 0.3)]
failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


def shear_stiffness(delta):
    return 6 * CHI * (1 - NU) / delta**2


def mindlin_harmonic(s):
    """W(r) of w = W(r) cos(theta) for q = r cos(theta), as above."""
    k = np.sqrt(2 * s / (1 - NU))

    def bessel(r):
        # I_1(k r) / I_1(k R) and its derivatives, scaled against overflow.
        x = k * r
        scale = np.exp(k * (r - R)) / ive(1, k * R)
        i1 = ive(1, x) * scale
        i1p = 0.5 * (ive(0, x) + ive(2, x)) * scale
        return i1, k * i1p, k * k * (i1 * (1 + 1 / x**2) - i1p / x)

    def terms(r):
        """W, psi_theta / sin and M_rr / cos of the solutions A, B, C and
        the particular one."""
        g, gp, gpp = (np.array([0, 0, v, 0]) for v in bessel(r))
        f = np.array([r, r**3, 0, r**5 / 192])
        fp = np.array([1, 3 * r**2, 0, 5 * r**4 / 192])
        fpp = np.array([0, 6 * r, 0, 20 * r**3 / 192])
        w = f - np.array([0, 8 * r, 0, r**3 / 8]) / s
        psi_r, psi_t = fp + g / r, -f / r - gp
        m_rr = fpp + gp / r - g / r**2 + NU * (psi_r + psi_t) / r
        return w, psi_t, m_rr

    rim = np.array(terms(R))
    coefficients = np.append(np.linalg.solve(rim[:, :3], -rim[:, 3]), 1.0)
    return np.vectorize(lambda r: terms(r)[0] @ coefficients)


def kirchhoff(r):
    rho = r / R
    return (R**4 * rho * (1 - rho**2) * ((7 + NU) - (3 + NU) * rho**2)
            / (192 * (3 + NU))) * R


def reference(point, radial):
    x, y = point
    r = np.hypot(x, y)
    return radial(r) * x / r


def scene(support, refinements, adaptive="false"):
    probes = "; ".join(f"{x}, {y}" for x, y in PROBES)
    return f"""
subsection Analysis
  set Type = static
end
subsection Plate
  set Thickness ratio = {DELTA}
  set Poisson ratio = {NU}
end
subsection Foundation
  set Model = none
end
subsection Discretization
  set Shape = disc
  set Radius = {R}
  set Global refinements = {refinements}
  set Polynomial degree = 2
end
subsection Mesh refinement
  set Adaptive = {adaptive}
  set Static cycles = 3
  set Maximum level = 4
end
subsection Boundary conditions
  set Outer = {support}
end
subsection Loads
  subsection Pressure 1
    set Region = whole plate
    set Magnitude = 1
    set Intensity = x
  end
end
subsection Output
  set VTU interval = 0
  set Write energies = false
  set Probe points = {probes}
end
"""


def error(work, name, text, radial):
    """Largest error of w at the probes relative to the largest |w|."""
    history = read_history(run_scene_or_fail(LIFTOFF, work, name, text))
    exact = np.array([reference(p, radial) for p in PROBES])
    computed = np.array([history[f"w({x:g};{y:g})"][-1] for x, y in PROBES])
    largest = max(abs(radial(r)) for r in np.linspace(0.01, R, 200))
    print(f"{name}: w {computed} against {exact}")
    return np.max(np.abs(computed - exact)) / largest


thin = mindlin_harmonic(shear_stiffness(1e-4))
rho = np.linspace(0.05, 1, 20) * R
thin_difference = np.max(np.abs(thin(rho) - kirchhoff(rho))) \
    / np.max(np.abs(kirchhoff(rho)))
check(thin_difference < 1e-6,
      f"closed form at Delta = 1e-4 against Kirchhoff's: {thin_difference:.2e}"
      f" < 1e-6")

radial = mindlin_harmonic(shear_stiffness(DELTA))
with tempfile.TemporaryDirectory() as work:
    errors = np.array([error(work, f"hard{r}", scene("hard simply supported",
                                                      r), radial)
                       for r in (1, 2, 3, 4)])
    rates = np.log2(errors[:-1] / errors[1:])
    print(f"errors {errors}, rates {rates}")
    check(np.all(rates >= 1.8), f"rates {rates} >= 1.8")
    check(errors[-1] < 1e-5, f"finest error {errors[-1]:.2e} < 1e-5")
    adapted = error(work, "adapted", scene("hard simply supported", 1,
                                           "true"), radial)
    check(adapted < errors[0] / 2,
          f"adapted mesh (hanging nodes): error {adapted:.2e} < "
          f"{errors[0]:.2e} / 2 of its start")
    soft = error(work, "soft3", scene("soft simply supported", 3), radial)
    check(soft > 100 * errors[-1],
          f"soft simple support differs by {soft:.2e} > 100 x "
          f"{errors[-1]:.2e}")
sys.exit(1 if failures else 0)
