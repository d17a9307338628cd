#!/usr/bin/env python3
"""A free circular plate of radius R = 1/2 on a tensionless Winkler bed
under a unit point load at its centre, no self weight, statics: the
contact radius c and the deflection against an axisymmetric Kirchhoff
solver written here, checked itself against the infinite plate's contact
radius (Weitsman 1970) derived here from Kelvin functions.

The solver. Lengths in l = (D / k)^(1/4), w in P l^2 / D (so D = k = P = 1),
rho = r / l, L = R / l. The contact zone is rho < c, the plate lifted
beyond it (w < 0, no springs). The point load's free-plate deflection
w_s = rho^2 ln(rho / L) / (8 pi) (lap^2 w_s = delta / (2 pi rho)) is split
off, and u = w - w_s, regular at the centre, solves

    lap^2 u = -(u + w_s)  for rho < c,   lap^2 u = 0  for rho > c,

as the first-order system y = (u, a = rho u', m = lap u, b = rho m') on
each zone, mapped to [0, 1] each (rho = c s and rho = c + (L - c) s),
eight unknowns and the parameter c for scipy.integrate.solve_bvp (the
1/rho terms at the centre through its singular term S): a = b = 0 at the
centre; u, a, m, b continuous at c (w, w', M_r and Q_r are); w(c) = 0;
free rim, M_r = Q_r = 0, i.e. lap w - (1 - nu) w' / rho = 0 and
(lap w)' = 0 at rho = L. The bed's springs push with w, which vanishes at
c, so the loading is continuous there. Checked: the bed carries P, and
w > 0 inside c and w < 0 beyond (the zones are what they were assumed).

The infinite plate. Inside c the deflection is -kei / (2 pi) + c1 ber +
c2 bei (tests/common/kelvin_disc.py); outside, a lifted weightless plate
carries no shear (the bed inside took all of P) and no moment at infinity,
so w = A0 + A1 ln rho, whose M_r = (1 - nu) w' / rho. Continuity of w',
M_r and Q_r at c gives lap w(c) = 0 and (lap w)'(c) = 0, which fix c1, c2;
w(c) = 0 then fixes c / l = 2.8489 (w(0) = 0.13117 P l^2 / D). The solver's
c at L = 10, 20, 40, 80 approaches it like L^-2 (the rim's moment
condition adds A2 rho^2 with A2 ~ 1 / L^2 to the outer plate).

liftoff: Gamma = 1e4 (l = 0.1, L = 5, c = 2.774 l), Delta = 1e-4 (see
free_disc_winkler.py for the Mindlin part), Q2 on the disc with 2 to 4
global refinements. c is read where w changes sign along a profile of 501
points on the x axis, and from the contact fraction, c = R sqrt(fraction)
(which counts Gauss points). Checks: c within 1e-4 (profile, measured
1.4e-5) and 1e-3 (fraction, measured 3.2e-4); w(0) within 3e-4 (measured
1.1e-4), converging at least like h^1.8 (measured 2.2, 2.1); w at
l, 4 l and R within 1e-4 of w(0).

    free_disc_tensionless.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np
from scipy import integrate, optimize

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from kelvin_disc import (LAPLACIAN, LAPLACIAN_SLOPE, KelvinDisc,  # noqa: E402
                         terms)
from scenes import (first_sign_change, read_history,  # noqa: E402
                    read_profile, run_scene_or_fail, static_disc_scene)

LIFTOFF = sys.argv[1]
R, NU, DELTA, GAMMA, P = 0.5, 0.3, 1e-4, 1e4, 1.0
ELL = GAMMA**-0.25
RADII = (0.0, ELL, 4 * ELL, R)


def split_off(rho, length):
    """w_s, w_s' and lap w_s at rho > 0."""
    log = np.log(rho / length)
    return (rho**2 * log / (8 * np.pi), rho * (2 * log + 1) / (8 * np.pi),
            (log + 1) / (2 * np.pi))


def tensionless_disc(length):
    """solve_bvp's solution on the two zones for a free disc of radius
    L = length; returns c and w(rho)."""
    def rhs(s, y, p):
        c, h = p[0], length - p[0]
        u1, a1, m1, b1, u2, a2, m2, b2 = y
        r1, r2 = c * s, c + h * s
        w_s = np.where(s > 0, split_off(np.maximum(r1, 1e-300), length)[0], 0)
        zero = np.zeros_like(s)
        # The centre's a1 / s and b1 / s are solve_bvp's singular term.
        return np.vstack((zero, c * c * s * m1, zero, -c * c * s * (u1 + w_s),
                          h * a2 / r2, h * r2 * m2, h * b2 / r2, zero))

    def conditions(ya, yb, p):
        _, slope_s, lap_s = split_off(length, length)
        rim_moment = (yb[6] + lap_s
                      - (1 - NU) * (yb[5] / length + slope_s) / length)
        return np.array([ya[1], ya[3], *(yb[:4] - ya[4:]),
                         yb[0] + split_off(p[0], length)[0], rim_moment,
                         yb[7] + 1 / (2 * np.pi)])

    singular = np.zeros((8, 8))
    singular[0, 1] = singular[2, 3] = 1
    s = np.linspace(0, 1, 201)
    solution = integrate.solve_bvp(
        rhs, conditions, s, np.zeros((8, s.size)), p=[min(2.8, length / 2)],
        S=singular, tol=1e-10, max_nodes=100000)
    assert solution.success, solution.message
    c = solution.p[0]

    def w(rho):
        rho = np.asarray(rho, dtype=float)
        inside = rho < c
        s = np.where(inside, rho / c, (rho - c) / (length - c))
        y = solution.sol(s)
        w_s = np.where(rho > 0, split_off(np.maximum(rho, 1e-300), length)[0],
                       0)
        return np.where(inside, y[0], y[4]) + w_s

    return c, w


def infinite_plate_contact():
    """Weitsman's contact radius c / l and w(0) of the infinite plate."""
    def solution(c):
        t = terms(c)
        return KelvinDisc(np.array([t[LAPLACIAN], t[LAPLACIAN_SLOPE]]))

    c = optimize.brentq(lambda c: solution(c).at(c), 2, 4, xtol=1e-14)
    return c, solution(c).at(0.0)


def scene(refinements):
    return static_disc_scene(
        R, refinements, {"Thickness ratio": DELTA, "Poisson ratio": NU},
        {"Model": "tensionless", "Stiffness": GAMMA}, (P, 0),
        {"Probe points": "; ".join(f"{r:g}, 0" for r in RADII),
         "Profile start": "0, 0", "Profile end": f"{R}, 0",
         "Profile points": 501})


def check_solver(length):
    c, w = tensionless_disc(length)
    rho = np.linspace(0, length, 2001)
    carried = integrate.quad(lambda r: w(r) * 2 * np.pi * r, 0, c,
                             epsabs=1e-13, epsrel=1e-11)[0]
    inside, outside = w(rho[rho < c]), w(rho[rho > c])
    print(f"solve_bvp, L = {length}: c = {c:.10f} l, w(0) = {w(0.0):.10f}, "
          f"bed reaction {carried:.12f} P")
    check(abs(carried - 1) < 1e-8 and np.all(inside > 0)
          and np.all(outside < 0), f"L = {length}: the bed carries P, "
          "w > 0 inside c and w < 0 beyond")
    return c, w


c_infinite, w0_infinite = infinite_plate_contact()
print(f"infinite plate (Kelvin functions): c = {c_infinite:.10f} l, "
      f"w(0) = {w0_infinite:.10f} P l^2 / D")
gaps = np.array([abs(check_solver(length)[0] - c_infinite)
                 for length in (10, 20, 40, 80)])
print(f"|c(L) - c_infinite| for L = 10, 20, 40, 80: {gaps}")
check(gaps[-1] < 2e-4 * c_infinite
      and np.all(np.abs(gaps[:-1] / gaps[1:] - 4) < 0.2),
      f"the large discs' c approaches the infinite plate's like L^-2: "
      f"{gaps[-1] / c_infinite:.2e} at L = 80, ratios "
      f"{gaps[:-1] / gaps[1:]}")

c_exact, w_exact = check_solver(R / ELL)
c_exact *= ELL
w_exact = P * ELL**2 * w_exact(np.array(RADII) / ELL)
with tempfile.TemporaryDirectory() as work:
    errors = []
    for refinements in (2, 3, 4):
        folder = run_scene_or_fail(LIFTOFF, work, f"disc{refinements}",
                                   scene(refinements))
        row = read_history(folder)
        w = np.array([row[f"w({r:g};0)"][0] for r in RADII])
        c_profile = first_sign_change(*read_profile(folder))
        c_fraction = R * np.sqrt(row["contact_fraction"][0])
        errors.append(np.concatenate((
            [abs(c_profile / c_exact - 1), abs(c_fraction / c_exact - 1)],
            np.abs(w - w_exact) / w_exact[0])))
        print(f"{refinements} refinements: c = {c_profile:.8f} (profile), "
              f"{c_fraction:.8f} (contact fraction), exact {c_exact:.8f}; "
              f"w = {w}, exact {w_exact}")
    errors = np.array(errors)
    print(f"relative errors (c profile, c fraction, w / w(0)):\n{errors}")
    rates = np.log2(errors[:-1, 2] / errors[1:, 2])
    check(errors[-1, 0] < 1e-4,
          f"c from the profile within {errors[-1, 0]:.2e} < 1e-4")
    check(errors[-1, 1] < 1e-3,
          f"c from the contact fraction within {errors[-1, 1]:.2e} < 1e-3")
    check(errors[-1, 2] < 3e-4 and np.all(rates >= 1.8),
          f"w(0) within {errors[-1, 2]:.2e} < 3e-4, rates {rates} >= 1.8")
    check(np.all(errors[-1, 3:] < 1e-4),
          f"w(l, 4l, R) within {errors[-1, 3:]} < 1e-4 of w(0)")
finish()
