"""The infinite plate on a Winkler bed under a uniform disc load (radius a,
pressure q = P / (pi a^2)), by the Hankel transform: the deflection basin

    w(r) = q a int_0^inf J1(xi a) J0(xi r) F(xi) dxi

with F = 1 / (D xi^4 + k) for the Kirchhoff plate and, for the Mindlin
plate of shear stiffness S = kappa G h (kappa = 5/6),

    F = (1 + D xi^2 / S) / (D xi^4 + k (1 + D xi^2 / S)),

from D lap^2 w = (1 - (D / S) lap)(q - k w): the shear strain adds the
deflection D xi^2 / S of each wave. Integrated with scipy between the
zeros of J1(xi a), after xi = s / l (l = (D / k)^(1/4)).
"""

import math

import numpy as np
from scipy import integrate, special


def basin(P, a, h, E, nu, k, offsets, mindlin=False, n_zeros=200):
    """w at each offset (m) for the load P (N) on the disc of radius a."""
    D = E * h**3 / (12 * (1 - nu**2))
    ell = (D / k) ** 0.25
    q = P / (math.pi * a * a)
    ratio = 0.0
    if mindlin:
        S = 5.0 / 6.0 * E / (2 * (1 + nu)) * h
        ratio = D / (S * ell * ell)  # D xi^2 / S at xi = s / l is ratio s^2
    edges = np.concatenate([[0.0], special.jn_zeros(1, n_zeros) * ell / a])

    def at(r):
        def f(s):
            g = 1 + ratio * s * s
            return (special.j1(s * a / ell) * special.j0(s * r / ell) * g
                    / (s**4 + g))
        return sum(integrate.quad(f, lo, hi, limit=200)[0]
                   for lo, hi in zip(edges[:-1], edges[1:]))

    # xi = s / l: D xi^4 + k = k (s^4 + 1), dxi = ds / l.
    return [q * a * at(r) / (k * ell) for r in offsets]
