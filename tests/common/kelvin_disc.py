"""The axisymmetric Kirchhoff plate on a Winkler bed under a central point
load, in Kelvin functions (Timoshenko and Woinowsky-Krieger, sec. 57-58),
for the Python tests of circular plates.

Lengths in the bed's radius of relative stiffness l = (D / k)^(1/4),
rho = r / l, w in P l^2 / D. Where the plate presses the bed,
lap^2 w + w = 0 away from the load, and the solutions regular at the
centre that carry the load P there are

    w = -kei(rho) / (2 pi) + c1 ber(rho) + c2 bei(rho)

(-kei / (2 pi) is the infinite plate's; ker is left out, its w is
log-singular). Since lap ber = -bei, lap bei = ber and lap kei = ker, the
Laplacian and the slopes are Kelvin functions again (derivatives in rho,
w here the dimensionless deflection): the radial moment is
M_r = -P (lap w - (1 - nu) w' / rho) and the shear force
Q_r = -(P / l) (lap w)' (a positive moment puts the bed side in tension,
as in liftoff).
"""

import numpy as np
from scipy import special

# Rows of terms(): the quantities the conditions are made of.
VALUE, SLOPE, LAPLACIAN, LAPLACIAN_SLOPE = range(4)


def terms(rho):
    """Columns: the particular part -kei / (2 pi), ber and bei; rows: value,
    slope d/drho, Laplacian and its slope, at rho."""
    two_pi = 2 * np.pi
    return np.array([
        [-special.kei(rho) / two_pi, special.ber(rho), special.bei(rho)],
        [-special.keip(rho) / two_pi, special.berp(rho), special.beip(rho)],
        [-special.ker(rho) / two_pi, -special.bei(rho), special.ber(rho)],
        [-special.kerp(rho) / two_pi, -special.beip(rho), special.berp(rho)],
    ])


def free_edge_rows(rho, nu):
    """M_r = 0 and Q_r = 0 at rho, as rows on (1, c1, c2)."""
    t = terms(rho)
    return np.array([t[LAPLACIAN] - (1 - nu) * t[SLOPE] / rho,
                     t[LAPLACIAN_SLOPE]])


class KelvinDisc:
    """w = -kei / (2 pi) + c1 ber + c2 bei with c1, c2 chosen so that the
    two rows (on (1, c1, c2)) vanish."""

    def __init__(self, rows):
        c = np.linalg.solve(rows[:, 1:], -rows[:, 0])
        self.coefficients = np.concatenate(([1.0], c))

    def at(self, rho, row=VALUE):
        return terms(rho)[row] @ self.coefficients

    def radial_moment(self, rho, nu):
        """M_r / P; at rho = 0 the moment is log-singular."""
        return -(self.at(rho, LAPLACIAN)
                 - (1 - nu) * self.at(rho, SLOPE) / rho)
