"""The infinite Kirchhoff plate on a Winkler bed under a uniform pressure
on a square, in Kelvin functions (Hetenyi 1946; Timoshenko and
Woinowsky-Krieger, sec. 57), evaluated with scipy, for the Python tests.

For a unit point load on an infinite plate of bending stiffness D on a bed
of modulus k, l = (D / k)^(1/4) its radius of relative stiffness, at
distance r, rho = r / l:

    w    = -(l^2 / (2 pi D)) kei(rho)
    M_r  = (1 / (2 pi)) (ker(rho) - (1 - nu) kei'(rho) / rho)
    M_th = (1 / (2 pi)) (nu ker(rho) + (1 - nu) kei'(rho) / rho)

(a positive moment puts the bed-side face in tension, as in liftoff). The
pressure on the square |x|, |y| <= b is the integral of these over the
square; at the centre the integrand is log-singular and is integrated in
polar coordinates over the eight triangles of the square.
"""

import math

import numpy as np
from scipy import integrate, special


class KelvinSquare:
    """A unit force spread over the square |x|, |y| <= b on the infinite
    plate (D, nu) with radius of relative stiffness `ell`."""

    def __init__(self, ell, nu, b, D=1.0):
        self.ell, self.nu, self.b, self.D = ell, nu, b, D
        self.q = 1.0 / (2 * b) ** 2

    def green(self, dx, dy):
        """w, M_xx, M_yy at offset (dx, dy) from a unit point load."""
        ell, nu = self.ell, self.nu
        r = math.hypot(dx, dy)
        rho = r / ell
        w = -(ell ** 2) / (2 * math.pi * self.D) * special.kei(rho)
        kp = special.keip(rho) / rho
        m_r = (special.ker(rho) - (1 - nu) * kp) / (2 * math.pi)
        m_t = (nu * special.ker(rho) + (1 - nu) * kp) / (2 * math.pi)
        c2, s2 = (dx / r) ** 2, (dy / r) ** 2
        return np.array([w, m_r * c2 + m_t * s2, m_r * s2 + m_t * c2])

    def at_centre(self, k):
        """w (k = 0) or M_xx = M_yy (k = 1) at the square's centre."""
        # Eight triangles 0 <= theta <= pi/4, 0 < r <= b / cos(theta),
        # which the square's symmetries map onto each other; a swap of x
        # and y is one of them, so M_xx = M_yy = their mean at the centre.
        def integrand(r, theta):
            g = self.green(r * math.cos(theta), r * math.sin(theta))
            return (g[0] if k == 0 else 0.5 * (g[1] + g[2])) * r

        value, _ = integrate.dblquad(
            integrand, 0, math.pi / 4, 0, lambda t: self.b / math.cos(t),
            epsabs=1e-13, epsrel=1e-10)
        return 8 * self.q * value

    def at_point(self, x, y, k):
        """w, M_xx or M_yy (k = 0, 1, 2) at (x, y) off the square."""
        b = self.b
        value, _ = integrate.dblquad(
            lambda sy, sx: self.green(x - sx, y - sy)[k], -b, b, -b, b,
            epsabs=1e-13, epsrel=1e-10)
        return self.q * value
