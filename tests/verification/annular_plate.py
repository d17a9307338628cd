#!/usr/bin/env python3
"""An annular plate a_i <= r <= a (a_i = 0.2, a = 0.5) under a uniform
pressure q, without foundation, statics: the deflection at the radii a_i,
(a_i + a) / 2 and a on the x axis against the axisymmetric Mindlin plate
solved here by scipy.integrate.solve_bvp (tolerance 1e-10), in liftoff's
units (D = 1, shear stiffness S = 6 chi (1 - nu) / Delta^2). With the
rotation beta (~ dw/dr), m_r = D (beta' + nu beta / r),
m_t = D (nu beta' + beta / r) and Q = S (w' - beta), the radial equations
are

    (r Q)' = -q r,    (r m_r)' - m_t + r Q = 0,

held by w = beta = 0 (clamped), w = 0 and m_r = 0 (soft simply
supported; under an axisymmetric load the tangential rotation vanishes by
symmetry) or m_r = Q = 0 (free). Two cases, each holding one circle and
leaving the other free: clamped at the hole (a footing ring on a column)
and soft simply supported at the rim. The bvp is checked against the
Kirchhoff closed form of Timoshenko and Woinowsky-Krieger (ch. 3, the
plate simply supported at the outer edge, free at the hole) plus the
shear deflection, which is what it is for a statically determinate ring:
the shear force Q(r) = -q (r^2 - a_i^2) / (2 r) is known, and the shear
adds int Q / S dr.

The annulus is GridGenerator::hyper_shell with its SphericalManifold and a
MappingQ2, Q2 elements, 1 to 3 global refinements. Checks: the largest
relative error of the three deflections falls at least like h^2 over the
refinements and is below 1e-4 on the finest mesh (measured: rates 3.7 to 3.9,
errors 3.0e-5 clamped at the hole, 4.9e-6 supported at the rim). With
MappingQ1 (a polygonal ring) the bound fails (1.7e-3 and 7.9e-3).

    annular_plate.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np
from scipy.integrate import quad, solve_bvp

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (pressed_plate, read_history,  # noqa: E402
                    run_scene, run_scene_or_fail, scene_text)

LIFTOFF = sys.argv[1]
AI, A, Q, NU, CHI, DELTA = 0.2, 0.5, 1.0, 0.3, 5.0 / 6.0, 0.05
S = 6 * CHI * (1 - NU) / DELTA**2
RADII = (AI, (AI + A) / 2, A)

def radial(r, y):
    """y = (w, beta, r m_r, r Q)."""
    w, beta, rm, rq = y
    dbeta = rm / r - NU * beta / r
    m_t = NU * dbeta + beta / r
    return np.vstack((beta + rq / (r * S), dbeta, m_t - rq, -Q * r))


def axisymmetric(inner, outer):
    """w at RADII for the conditions on the hole's and the rim's circle."""
    def held(y, condition):
        w, beta, rm, rq = y
        return {"clamped": [w, beta], "soft simply supported": [w, rm],
                "free": [rm, rq]}[condition]

    r = np.linspace(AI, A, 201)
    solution = solve_bvp(radial, lambda ya, yb: np.array(
        held(ya, inner) + held(yb, outer)), r, np.zeros((4, r.size)),
        tol=1e-10, max_nodes=100000)
    assert solution.success, solution.message
    return solution.sol(np.array(RADII))[0]


def kirchhoff_simply_supported_rim(r):
    """w(r) of the annulus supported at the rim, free at the hole: the
    Kirchhoff slope beta from (1/r (r beta)')' = q (r^2 - a_i^2) / (2 r),
    beta = C1 r + C2 / r + a particular solution with m_r(a_i) = m_r(a) = 0,
    plus the shear slope Q / S, integrated from the rim by quad."""
    def particular(x):
        return Q * (x**3 / 16 - AI**2 * x * (2 * np.log(x) - 1) / 8)

    def dparticular(x):
        return Q * (3 * x**2 / 16 - AI**2 * (2 * np.log(x) + 1) / 8)

    def m_r(c1, c2, x):
        beta = c1 * x + c2 / x + particular(x)
        return (c1 - c2 / x**2 + dparticular(x)) + NU * beta / x

    matrix = np.array([[1 + NU, -(1 - NU) / AI**2], [1 + NU, -(1 - NU) / A**2]])
    rhs = -np.array([m_r(0, 0, AI), m_r(0, 0, A)])
    c1, c2 = np.linalg.solve(matrix, rhs)

    def slope(x):
        shear = -Q * (x**2 - AI**2) / (2 * x) / S
        return c1 * x + c2 / x + particular(x) + shear

    return -quad(slope, r, A, epsabs=1e-14, epsrel=1e-13)[0]


def scene(inner, outer, refinements):
    return scene_text(
        pressed_plate(DELTA, NU, Q),
        {"Discretization": {"Shape": "annulus", "Radius": A,
                            "Inner radius": AI,
                            "Global refinements": refinements},
         "Boundary conditions": {"Inner": inner, "Outer": outer},
         "Output": {"Probe points": "; ".join(f"{r}, 0" for r in RADII)}})


def run(work, name, text):
    history = read_history(run_scene_or_fail(LIFTOFF, work, name, text))
    return np.array([history[f"w({r:g};0)"][0] for r in RADII])


reference = axisymmetric("free", "soft simply supported")
closed = np.array([kirchhoff_simply_supported_rim(r) for r in RADII])
print("bvp against the closed form (rim supported):", reference, closed)
check(np.max(np.abs(reference[:2] / closed[:2] - 1)) < 1e-8
      and abs(reference[2]) < 1e-12,
      "solve_bvp reproduces the closed form plus shear to 1e-8")

with tempfile.TemporaryDirectory() as work:
    for inner, outer in (("clamped", "free"), ("free", "soft simply supported")):
        exact = axisymmetric(inner, outer)
        errors = []
        for r in (1, 2, 3):
            w = run(work, f"{inner[:4]}{outer[:4]}{r}", scene(inner, outer, r))
            # w vanishes on the held circle: absolute there, relative to
            # the largest deflection elsewhere.
            errors.append(np.max(np.abs(w - exact)) / np.max(np.abs(exact)))
            print(f"Inner {inner}, Outer {outer}, {r} refinements: w = {w}, "
                  f"exact {exact}, error {errors[-1]:.3e}")
        rates = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
        print("rates", rates)
        check(np.all(rates > 1.9), f"Inner {inner}, Outer {outer}: error "
              "falls at least like h^2")
        check(errors[-1] < 1e-4, f"Inner {inner}, Outer {outer}: error "
              f"{errors[-1]:.2e} < 1e-4 on 3 refinements")

    # The default probe (0, 0) lies in the hole: the scene runs without it
    # and says so.
    text = scene("clamped", "free", 0).replace("set Probe points", "#")
    folder, result = run_scene(LIFTOFF, work, "default_probe", text)
    columns = read_history(folder) if result.returncode == 0 else {}
    check(result.returncode == 0 and "in the annulus's hole" in result.stdout
          and not any(c.startswith("w(") for c in columns),
          "an annulus without Probe points runs, with no probe column and "
          f"a note (exit {result.returncode}: {result.stderr.strip()})")

finish()
