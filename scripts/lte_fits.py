"""The load transfer efficiency of an aggregate-interlock joint as a
function of the dimensionless joint stiffness f = AGG / (k l), l = (D /
k)^(1/4) the radius of relative stiffness, D = E h^3 / (12 (1 - nu^2)),
and the fits' inverses (AGG from a measured LTE). LTE in per cent, 100
w_unloaded / w_loaded at the joint under a load tangent to it. Two fits of
finite element results, neither exact (they differ by up to 4 points):

- Crovetti (1994): LTE = 100 / (1 + 1.2 f^-0.849);
- Ioannides and Hammons (1996), for a load of radius a:
  LTE = 100 / (1 + 10^((0.214 - 0.183 a/l - log10 f) / 1.18)).

Used by scripts/liftoff-backcalc (the start of a joint's fit) and by the
joint tests.
"""

import math


def radius_of_relative_stiffness(E, h, nu, k):
    return (E * h**3 / (12 * (1 - nu**2)) / k) ** 0.25


def crovetti(f):
    return 100 / (1 + 1.2 * f**-0.849)


def ioannides_hammons(f, a_over_l):
    return 100 / (1 + 10 ** ((0.214 - 0.183 * a_over_l - math.log10(f))
                             / 1.18))


def check_lte(lte):
    if not 0 < lte < 100:
        raise ValueError("an LTE of %g %% is outside (0, 100) %%, where the "
                         "fits have a joint stiffness" % lte)


def crovetti_inverse(lte):
    """f with crovetti(f) = lte."""
    check_lte(lte)
    return (1.2 / (100 / lte - 1)) ** (1 / 0.849)


def ioannides_hammons_inverse(lte, a_over_l):
    """f with ioannides_hammons(f, a_over_l) = lte."""
    check_lte(lte)
    return 10 ** (0.214 - 0.183 * a_over_l - 1.18 * math.log10(100 / lte - 1))
