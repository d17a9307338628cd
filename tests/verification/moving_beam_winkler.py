#!/usr/bin/env python3
"""A constant force crossing a long free strip on a bilateral, damped
Winkler bed, against the steady state of the infinite beam (Kenney 1954;
Fryba, Vibration of Solids and Structures under Moving Loads, ch. 8),
computed here with numpy and not by liftoff.

In liftoff's units (doc/model.md, "Moving loads") a strip of width mu,
nu = 0, free long edges and a pressure uniform across its width bends as a
beam of EI = D = 1, m = rho H = 1 per unit width on springs Gamma and
dashpots c (Foundation/Damping):

    w'''' + w_tautau + c w_tau + Gamma w = q(x - v tau).

In the frame of the load, s = x - v tau, the steady state solves

    w'''' + v^2 w'' - c v w' + Gamma w = q(s),

whose characteristic quartic r^4 + v^2 r^2 - c v r + Gamma has (for c > 0)
two roots with Re r < 0 (the basin ahead, s > 0) and two with Re r > 0
(behind). The force P at s = 0 makes w, w', w'' continuous and w''' jump
by P: four linear equations for the four amplitudes. A pressure q on
|s| <= a/2 (a `Patch load` as wide as the strip) is that Green's function
integrated over the patch, in closed form for exponentials. With c = 0 the
critical speed, where the basin's roots reach the imaginary axis, is
v_cr = (4 Gamma)^(1/4).

The strip: Gamma = 4e6 (l = Gamma^(-1/4) = 0.0224, so the plate is 45 l
long), mu = 0.02, Delta = 0.001 (shear and rotary inertia change w by
about (Delta / l)^2 = 2e-3), 224 x 1 Q2 cells (h = l / 5), dt = h / (2 v),
dashpots of 0.3 of the bed's critical damping (c = 0.6 sqrt(Gamma)): the
start's transient must die out over the 27 l the load travels before the
probe (with 0.1 of critical and 16 l the basin was off by 0.17 at 0.9
v_cr; a finer mesh did not change that). The patch (a = 2 h) starts at
x = -0.45, ramps in over its first 4 l and crosses at speed v; a probe at x = 0.15 sees the basin pass: w(0.15, tau) =
w_ss(0.15 - X(tau)). Checks at v / v_cr = 0.5, 0.9 and 1.5:
- the deflection under the load (the probe's w when the load's centre
  passes it) within 1 % of the basin's largest |w| (above v_cr w under
  the load is near 0); measured 5.7e-5, 9.2e-4, 3.1e-3;
- the basin from 4 l ahead of the load to 6 l behind it within 1.5 % of the
  closed form's largest |w|; measured 4.7e-4, 3.7e-3, 7.8e-3;
- the profile that rides with the load (Output/Profile follows), taken
  when the load is over the probe, from 6 l behind to 4 l ahead: its
  points where the load is (to 3.0e-12) and its w within 1.5 % of the
  closed form's largest |w|; measured 5.4e-4, 3.3e-3, 4.2e-3 (with the
  line standing at its offsets: 1.0, 1.05, 1.35);
- the closed form itself: its static limit is Hetenyi's
  P / (8 beta^3) e^(-beta |s|) (cos + sin)(beta |s|), beta^4 = Gamma / 4,
  and it satisfies its ODE (finite differences) on both sides.

    moving_beam_winkler.py LIFTOFF
"""

import math
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402

GAMMA = 4.0e6
ELL = GAMMA ** -0.25
V_CR = (4 * GAMMA) ** 0.25
DAMPING = 0.6 * math.sqrt(GAMMA)
WIDTH = 0.02
CELLS = 224
H = 1.0 / CELLS
PATCH = 2 * H
PRESSURE = 1.0 / PATCH  # a unit force per unit width
START = -0.45
LIFTOFF = None  # the binary, from the command line
PROBE = 0.15


class SteadyState:
    """The beam's steady deflection in the frame of the load."""

    def __init__(self, v, c=DAMPING, gamma=GAMMA):
        roots = np.roots([1.0, 0.0, v * v, -c * v, gamma])
        self.ahead = roots[roots.real < 0]
        self.behind = roots[roots.real > 0]
        assert len(self.ahead) == 2 and len(self.behind) == 2, roots
        # w, w', w'' continuous at s = 0, w''' jumps by the unit force.
        powers = np.arange(4)[:, None]
        system = np.hstack([self.ahead[None, :] ** powers,
                            -self.behind[None, :] ** powers])
        amplitudes = np.linalg.solve(system, [0, 0, 0, 1])
        self.a_ahead, self.a_behind = amplitudes[:2], amplitudes[2:]

    def point(self, s):
        """w at s of a unit force at s = 0."""
        s = np.asarray(s, dtype=float)
        ahead = (self.a_ahead * np.exp(np.outer(np.maximum(s, 0),
                                                self.ahead))).sum(axis=1)
        behind = (self.a_behind * np.exp(np.outer(np.minimum(s, 0),
                                                  self.behind))).sum(axis=1)
        return np.where(s >= 0, ahead, behind).real

    def patch(self, s, a=PATCH, q=PRESSURE):
        """w at s of the pressure q on |s| <= a/2: the point's w integrated
        over the patch, int e^(r (s - t)) dt in closed form."""
        s = np.atleast_1d(np.asarray(s, dtype=float))[:, None]
        lo, hi = -a / 2, a / 2
        # The patch's part behind s (t < s) sees the basin ahead of it.
        t1 = np.minimum(hi, s)
        ahead = np.where(s > lo, (self.a_ahead / self.ahead) * (
            np.exp(self.ahead * (s - lo)) - np.exp(self.ahead * (s - t1))),
            0).sum(axis=1)
        t0 = np.maximum(lo, s)
        behind = np.where(s < hi, (self.a_behind / self.behind) * (
            np.exp(self.behind * (s - t0)) - np.exp(self.behind * (s - hi))),
            0).sum(axis=1)
        return q * (ahead + behind).real


def check_closed_form():
    s = np.linspace(-5 * ELL, 5 * ELL, 41)
    beta = (GAMMA / 4) ** 0.25
    hetenyi = (np.exp(-beta * abs(s)) / (8 * beta ** 3)
               * (np.cos(beta * s) + np.sin(beta * abs(s))))
    error = abs(SteadyState(1e-9, 0).point(s) - hetenyi).max() / hetenyi[20]
    check(error < 1e-10, f"closed form: static limit = Hetenyi's to "
          f"{error:.1e} (< 1e-10)")
    for ratio in (0.5, 0.9, 1.5):
        v = ratio * V_CR
        beam = SteadyState(v)
        h = 1e-2 * ELL
        largest = abs(beam.point(np.linspace(-6 * ELL, 4 * ELL, 401))).max()
        worst = 0
        for s0 in (-2.3 * ELL, -0.7 * ELL, 0.6 * ELL, 1.9 * ELL):
            w = beam.point(s0 + h * np.arange(-2, 3))
            d4 = (w[4] - 4 * w[3] + 6 * w[2] - 4 * w[1] + w[0]) / h ** 4
            d2 = (w[3] - 2 * w[2] + w[1]) / h ** 2
            d1 = (w[3] - w[1]) / (2 * h)
            residual = d4 + v * v * d2 - DAMPING * v * d1 + GAMMA * w[2]
            worst = max(worst, abs(residual) / (GAMMA * largest))
        check(worst < 1e-3, f"closed form at v/v_cr = {ratio}: ODE residual "
              f"{worst:.1e} of Gamma max|w| (< 1e-3, finite differences)")


def scene(v, folder, model="bilateral", end=None, loads="", output=""):
    """The strip with the patch crossing at speed v until `end` (by default
    7 l past the probe); `loads` and `output` are more entries of those
    subsections (moving_beam_tensionless.py's weight and profiles)."""
    if end is None:
        end = (PROBE + 7 * ELL - START) / v
    steps = round(end / (H / (2 * v)))
    ramp = 4 * ELL / v
    return f"""
subsection Plate
  set Aspect ratio = {WIDTH}
  set Thickness ratio = 0.001
  set Poisson ratio = 0
end
subsection Foundation
  set Model = {model}
  set Stiffness = {GAMMA}
  set Damping = {DAMPING}
end
subsection Discretization
  set Cells along x = {CELLS}
  set Cells along y = 1
  set Polynomial degree = 2
end
subsection Loads
{loads}  subsection Patch load 1
    set Magnitude = {PRESSURE}
    set Size = {PATCH}, 1
    set Path = {START} + {v!r}*tau; 0
    set Time history = if(tau < {ramp!r}, sin(pi/2*tau/{ramp!r})^2, 1)
  end
end
subsection Time integration
  set Time step = {end / steps!r}
  set End time = {end!r}
end
subsection Output
  set Directory = {folder}
  set VTU interval = 0
  set Write energies = false
  set Probe points = {PROBE}, 0
{output}end
"""


def riding_profile(v):
    """The basin around the load when it is over the probe, 6 l behind to
    4 l ahead, by a profile that rides with it."""
    return f"""  set Profile follows = patch_load_1
  set Profile start = {-6 * ELL!r}, 0
  set Profile end = {4 * ELL!r}, 0
  set Profile points = 101
  set Profile times = {(PROBE - START) / v!r}
"""


def run(v, work):
    folder = os.path.join(work, f"out{v:.3f}")
    prm = folder + ".prm"
    with open(prm, "w") as f:
        f.write(scene(v, folder, output=riding_profile(v)))
    subprocess.run([LIFTOFF, prm], check=True, stdout=subprocess.DEVNULL)
    path = os.path.join(folder, "history.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    profile = np.loadtxt(os.path.join(folder, "profiles.csv"), delimiter=",",
                         skiprows=1, ndmin=2)
    return (data[:, header.index("tau")],
            data[:, header.index(f"w({PROBE};0)")], profile)


def measure(v, work):
    """liftoff's and the closed form's w under the load, the basin's error
    and its largest |w| at speed v."""
    tau, w, profile = run(v, work)
    beam = SteadyState(v)
    # The probe's offset from the load's centre: s = x - X(tau).
    s = PROBE - (START + v * tau)
    window = (s <= 4 * ELL) & (s >= -6 * ELL)
    scale = abs(beam.patch(np.linspace(-6 * ELL, 4 * ELL, 401))).max()
    basin = abs(w[window] - beam.patch(s[window])).max() / scale
    under = np.interp(0, -s[window], w[window])
    # The profile that rides with the load: its s runs from 6 l behind, its
    # x from where the load is at the profile's time.
    p_tau, p_s, p_x, p_w = profile[:, 0], profile[:, 1], profile[:, 2], \
        profile[:, 4]
    p_offset = p_s - 6 * ELL
    placed = abs(p_x - (START + v * p_tau + p_offset)).max()
    riding = abs(p_w - beam.patch(p_offset)).max() / scale
    return under, beam.patch(0)[0], basin, scale, riding, placed


def compare(ratio, work):
    under, under_exact, basin, scale, riding, placed = measure(ratio * V_CR,
                                                               work)
    error = abs(under - under_exact) / scale
    print(f"v/v_cr = {ratio}: w under the load {under:.6e}, closed form "
          f"{under_exact:.6e}; largest |w| of the basin {scale:.6e}")
    check(error < 0.01, f"v/v_cr = {ratio}: w under the load off by "
          f"{error:.2e} of the basin's largest |w| (< 1e-2)")
    check(basin < 0.015, f"v/v_cr = {ratio}: basin from 4 l ahead to 6 l "
          f"behind off by {basin:.2e} of its largest |w| (< 1.5e-2)")
    check(placed < 1e-9, f"v/v_cr = {ratio}: the riding profile's points lie "
          f"where the load is, to {placed:.1e} (< 1e-9)")
    check(riding < 0.015, f"v/v_cr = {ratio}: the basin of the profile that "
          f"rides with the load over the probe, 4 l ahead to 6 l behind, off by "
          f"{riding:.2e} of its largest |w| (< 1.5e-2)")


if __name__ == "__main__":
    LIFTOFF = sys.argv[1]
    check_closed_form()
    with tempfile.TemporaryDirectory() as work:
        for ratio in (0.5, 0.9, 1.5):
            compare(ratio, work)
    finish()
