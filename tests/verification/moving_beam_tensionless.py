#!/usr/bin/env python3
"""The strip of moving_beam_winkler.py with self-weight on a TENSIONLESS
damped bed: the force lifts the strip off ahead of and behind it (Choros
and Adams 1979; Lin and Adams 1987). Against the steady state of the
infinite beam in the frame of the load, solved here with scipy and not by
liftoff.

In the frame of the load, s = x - v tau, with weight q and the pressure
q_P = P / a of the patch on |s| <= a/2, the beam (EI = m = 1 per unit
width, doc/model.md "Moving loads") solves

    w'''' + v^2 w'' + [contact] (Gamma w - c v w') = q + q_P [|s| <= a/2],

and liftoff's contact rule (doc/model.md, "Damping that never pulls") is
the sign of the bed's pressure p = Gamma w + c w_tau = Gamma w - c v w'.
The weight keeps the strip on the bed far from the load (w -> q / Gamma);
between the zone ends a2 > a1 > a/2 ahead and b2 < b1 < -a/2 behind it is
lifted. On each zone the equation has constant coefficients, so the state
(w, w', w'', w''') is carried across a zone of length L exactly by the
exponential of its 5 x 5 companion matrix (the constant load as a fifth
component). Unknowns: the state at s = 0 and a1, a2, b1, b2 (8); equations:
p = 0 at the four ends, and beyond a2 and b2 the state less q / Gamma lies
in the subspace that decays away from the load (2 + 2 conditions, by an
ordered real Schur form of the bed's 4 x 4 matrix; with c > 0 two roots
lie on each side at every speed). scipy.optimize.root solves them, walking
up in speed from 0.02 v_cr. Zone ends enter as log lengths, and the second
end's condition as the divided difference (p(a2) - p(a1)) / (a2 - a1),
since a lifted zone of zero length would satisfy p = 0 twice.

The reference is checked on its own: made bilateral it is Kenney's closed
form (moving_beam_winkler.py) plus q / Gamma; at v = 0 it is a finite
difference beam (l / 40, free ends 25 l out, active set) to 1e-3 l; at the
test speeds it keeps p > 0 on the bed and p < 0 off it, and the bed carries
P plus the weight of the lifted length (global equilibrium).

The single lifted zone on each side exists up to a fold: with q = 0.45
(0.66 of the weight that holds the static strip on the bed) the ahead
zone's end a2 grows with infinite slope at v = 0.428 v_cr, and no
solution of this form exists above (doc/studies.md, "The strip on a
tensionless bed"). Near the fold the lifted span ahead, which no dashpot
damps, breathes long after the start (a2 swings by 1.5 l at 0.3 v_cr
after 30 l of travel), so the test runs 0.15 and 0.22 v_cr. Checks, in
profiles of liftoff's w with the load at X = 0.15, 0.175, 0.2 (27 l to
29 l of travel; the strip's end 13 l ahead), p by differences of the
profile, the worst of the three:
- the four contact ends (the sign changes of p within 14 l of the load)
  within 0.01 l (0.15 v_cr) and 0.1 l (0.22 v_cr) of the reference's;
  measured 1.5e-3 l and 3.0e-2 l;
- w under the load (the riding probe) within 1e-3 of the reference's;
  measured 2.2e-4 and 2.9e-4 (8e-6 and 6.7e-5 with Delta = 3e-4: the
  Mindlin strip's shear against the reference's Euler-Bernoulli beam);
- the basin within 14 l of the load within 3e-3 and 1e-2 of w under the
  load; measured 3.7e-4 and 2.2e-3.
448 cells (with the step h / (2 v) halved with them) or the step alone
halved change the ends by at most 1.2e-3 l; at 0.22 v_cr a2 swings by 0.05 l
between the three profiles on both meshes alike: the start's transient.
With a bilateral bed the ends are off by 0.77 l and 1.05 l, w under the
load by 1.5e-3 and 2.4e-3, the basin by 3.4e-2 and 5.8e-2 (6 checks fail);
with the reference's a2 moved by 0.05 l the ends at 0.15 v_cr are off by
5.1e-2 l and the basin by 3.9e-3 (2 checks fail).

    moving_beam_tensionless.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np
import scipy.integrate
import scipy.linalg
import scipy.optimize
import scipy.sparse
import scipy.sparse.linalg

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
sys.path.insert(0, os.path.dirname(__file__))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene_or_fail  # noqa: E402
import moving_beam_winkler as strip  # noqa: E402

WEIGHT = 0.45
ELL = strip.ELL
HALF = strip.PATCH / 2
LOAD_AT = (0.15, 0.175, 0.2)
WINDOW = 14 * ELL
# The state's scale: w ~ 1e-6 and its derivatives in units of l.
STATE = 1e-6 / ELL ** np.arange(4)


class SteadyLiftoff:
    """The steady state in the frame of the load, with one lifted zone
    ahead of the patch and one behind it."""

    def __init__(self, v, q=WEIGHT, c=strip.DAMPING, bilateral=False):
        self.v, self.q, self.c = v, q, c
        self.patch = self.system(True, q + strip.PRESSURE)
        self.bed = self.system(True, q)
        self.lifted = self.bed if bilateral else self.system(False, q)
        self.far = np.array([q / strip.GAMMA, 0, 0, 0])
        # Subspaces in the state's units, so that w''' does not swamp w.
        scale = np.diag(1 / STATE)
        bed = scale @ self.bed[:4, :4] @ np.linalg.inv(scale)
        self.rising_ahead = self.complement(bed, "lhp") @ scale
        self.rising_behind = self.complement(bed, "rhp") @ scale
        self.x = None

    def system(self, contact, load):
        """d/ds of (w, w', w'', w''', 1) on a zone."""
        a = np.diag(np.ones(4), 1)
        bed = strip.GAMMA if contact else 0
        a[3] = [-bed, self.c * self.v if contact else 0, -self.v ** 2, 0,
                load]
        return a

    @staticmethod
    def complement(matrix, decaying):
        """Rows that vanish on the two roots' subspace that decays."""
        _, vectors, count = scipy.linalg.schur(matrix, output="real",
                                               sort=decaying)
        assert count == 2, np.linalg.eigvals(matrix)
        return vectors[:, 2:].T

    def pressure(self, z):
        return strip.GAMMA * z[0] - self.c * self.v * z[1]

    def zones(self, x):
        """(start, end, matrix, state at start) of every zone, from s = 0
        outwards, ahead and then behind; the state (w, w', w'', w''', 1)
        is carried across each zone by its exponential."""
        a1, a2, b1, b2 = x[4:]
        zones = []
        for side, first, second in ((1, a1, a2), (-1, b1, b2)):
            z, here = np.append(x[:4], 1.0), 0.0
            for end, matrix in ((side * HALF, self.patch), (first, self.bed),
                                (second, self.lifted),
                                (side * np.inf, self.bed)):
                zones.append((here, end, matrix, z))
                if np.isfinite(end):
                    z = scipy.linalg.expm(matrix * (end - here)) @ z
                    here = end
        return zones

    def residual(self, x):
        a1, a2, b1, b2 = x[4:]
        # The states at the ends: where the zones after them start.
        zones = self.zones(x)
        z1, z2, y1, y2 = (zones[k][3] for k in (2, 3, 6, 7))
        p = [self.pressure(z) for z in (z1, z2, y1, y2)]
        return np.concatenate([
            np.array([p[0], ELL * (p[1] - p[0]) / (a2 - a1),
                      p[2], ELL * (p[3] - p[2]) / (b2 - b1)]) / self.q,
            self.rising_ahead @ (z2[:4] - self.far),
            self.rising_behind @ (y2[:4] - self.far)])

    @staticmethod
    def unpack(u):
        a1 = HALF + ELL * np.exp(u[4])
        b1 = -HALF - ELL * np.exp(u[6])
        return np.concatenate([u[:4] * STATE, [a1, a1 + ELL * np.exp(u[5]),
                                               b1, b1 - ELL * np.exp(u[7])]])

    @staticmethod
    def pack(x):
        a1, a2, b1, b2 = x[4:]
        return np.concatenate([x[:4] / STATE, np.log(
            np.array([a1 - HALF, a2 - a1, -HALF - b1, b1 - b2]) / ELL)])

    def solve(self, guess):
        result = scipy.optimize.root(lambda u: self.residual(self.unpack(u)),
                                     self.pack(guess), method="hybr",
                                     options={"xtol": 1e-13})
        self.x = self.unpack(result.x)
        return result.success and abs(result.fun).max() < 1e-9

    def profile(self, s):
        """The states at the points s, each carried from its zone's start."""
        states = []
        zones = self.zones(self.x)
        for t in np.ravel(s):
            for start, end, matrix, z in zones:
                if min(start, end) <= t <= max(start, end):
                    states.append(scipy.linalg.expm(matrix * (t - start)) @ z)
                    break
        return np.array(states)


# The static tensionless beam (Hetenyi's basin plus the weight) as a start:
# w, w', w'', w''' at s = 0 and the ends at 3.3 l and 6.8 l.
STATIC_GUESS = np.array([4e-6, 0, -7e-3, 0, 3.3 * ELL, 6.8 * ELL,
                         -3.3 * ELL, -6.8 * ELL])


def reference(ratio, q=WEIGHT, c=strip.DAMPING):
    """The steady state at v = ratio v_cr, walked up from 0.02 v_cr."""
    x = STATIC_GUESS
    for r in np.linspace(0.02, ratio, max(2, round(ratio / 0.02))):
        beam = SteadyLiftoff(r * strip.V_CR, q, c)
        assert beam.solve(x), f"no steady state at {r:.3f} v_cr"
        x = beam.x
    return beam


def static_differences(q=WEIGHT, reach=25):
    """The static beam by finite differences (h = a / 16, about l / 40):
    energy of w'' (free ends 25 l out), springs where w > 0, active set
    until it stops changing."""
    dx = HALF / 8
    s = np.arange(-round(reach * ELL / dx), round(reach * ELL / dx) + 1) * dx
    d2 = scipy.sparse.diags([1, -2, 1], [0, 1, 2],
                            shape=(len(s) - 2, len(s))) / dx ** 2
    bending = (d2.T @ d2) * dx
    # The patch's ends are nodes: half their cells are under it.
    patch = np.where(abs(s) < HALF - dx / 2, 1, 0.5 * (abs(s) < HALF + dx / 2))
    load = (q + strip.PRESSURE * patch) * dx
    contact = np.ones(len(s), dtype=bool)
    for _ in range(50):
        springs = scipy.sparse.diags(strip.GAMMA * dx * contact)
        w = scipy.sparse.linalg.spsolve((bending + springs).tocsc(), load)
        if np.array_equal(w > 0, contact):
            break
        contact = w > 0
    return s, w


def sign_changes(s, f):
    k = np.where(np.sign(f[:-1]) != np.sign(f[1:]))[0]
    return s[k] - f[k] * (s[k + 1] - s[k]) / (f[k + 1] - f[k])


def check_reference():
    # Bilateral: the lifted zones are bed too, the ends only breakpoints.
    v = 0.5 * strip.V_CR
    bilateral = SteadyLiftoff(v, bilateral=True)
    # The decay conditions are affine in the state at s = 0.
    def decay(y):
        return bilateral.residual(np.append(y * STATE, STATIC_GUESS[4:]))[4:]
    matrix = np.array([decay(e) - decay(0 * e) for e in np.eye(4)]).T
    y = np.linalg.solve(matrix, -decay(np.zeros(4)))
    bilateral.x = np.append(y * STATE, STATIC_GUESS[4:])
    s = np.linspace(-12 * ELL, 12 * ELL, 97)
    kenney = WEIGHT / strip.GAMMA + strip.SteadyState(v).patch(s)
    error = abs(bilateral.profile(s)[:, 0] - kenney).max() / kenney.max()
    check(error < 1e-10, f"reference made bilateral = Kenney + q/Gamma at "
          f"0.5 v_cr to {error:.1e} of max w (< 1e-10)")
    # Static: against finite differences.
    beam = SteadyLiftoff(0.0)
    assert beam.solve(STATIC_GUESS)
    s, w = static_differences()
    ends = np.sort(sign_changes(s, w))
    worst = abs(ends - np.sort(beam.x[4:])).max() / ELL
    under = abs(np.interp(0, s, w) - beam.x[0]) / beam.x[0]
    check(worst < 1e-3 and under < 1e-4, f"reference at v = 0 against finite "
          f"differences: ends to {worst:.1e} l (< 1e-3), w(0) to "
          f"{under:.1e} (< 1e-4)")


def check_steady_state(beam, ratio):
    """Signs of p on and off the bed, and the bed's resultant."""
    a1, a2, b1, b2 = beam.x[4:]
    s = np.linspace(-40 * ELL, 40 * ELL, 4001)
    states = beam.profile(s)
    p = beam.pressure(states.T)
    lifted = ((s > a1) & (s < a2)) | ((s > b2) & (s < b1))
    away = np.min(abs(s[:, None] - beam.x[None, 4:]), axis=1) > 0.01 * ELL
    wrong = np.sum(away & (lifted == (p > 0)))
    reaction = np.where(lifted, 0, p) - beam.q
    balance = abs(scipy.integrate.trapezoid(reaction, s) - 1)
    check(wrong == 0 and balance < 1e-4, f"reference at {ratio} v_cr: p "
          f"of the wrong sign at {wrong} of 4001 points (0), bed's "
          f"resultant - weight = P to {balance:.1e} (< 1e-4)")


def scene(v, load_at=LOAD_AT):
    """The strip with weight on the tensionless bed, run until the load is
    at load_at[-1], with profiles when it is at each of load_at."""
    times = ", ".join(repr((x - strip.START) / v) for x in load_at)
    output = f"""  set Riding probes = w@patch_load_1
  set Profile start = -0.5, 0
  set Profile end = 0.5, 0
  set Profile points = 4001
  set Profile times = {times}
"""
    return strip.scene(v, "unused", "tensionless",
                       (load_at[-1] - strip.START) / v,
                       f"  set Self weight = {WEIGHT}\n", output)


def run(ratio, work, load_at=LOAD_AT):
    """liftoff's profiles for the load at each X of load_at: a list of
    (s, w, p, w under the load), s = x - X, p by differences of w."""
    v = ratio * strip.V_CR
    folder = run_scene_or_fail(strip.LIFTOFF, work, f"r{ratio}",
                               scene(v, load_at))
    profiles = np.genfromtxt(os.path.join(folder, "profiles.csv"),
                             delimiter=",", names=True)
    history = read_history(folder)
    found = []
    for tau in np.unique(profiles["tau"]):
        row = profiles[profiles["tau"] == tau]
        s = row["x"] - (strip.START + v * tau)
        near = abs(s) < WINDOW
        w = row["w"][near]
        p = strip.GAMMA * w - strip.DAMPING * v * np.gradient(w, s[near])
        under = history["w@patch_load_1"][np.argmin(abs(history["tau"]
                                                        - tau))]
        found.append((s[near], w, p, under))
    return found


def measure(ratio, work, beam):
    """The worst contact end, w under the load and basin over LOAD_AT."""
    ends, under, basin = 0, 0, 0
    for s, w, p, w_load in run(ratio, work):
        found = sign_changes(s, p)
        ends = max(ends, abs(found - np.sort(beam.x[4:])).max() / ELL
                   if len(found) == 4 else np.inf)
        under = max(under, abs(w_load - beam.x[0]) / beam.x[0])
        basin = max(basin, abs(w - beam.profile(s)[:, 0]).max() / beam.x[0])
    return ends, under, basin


def compare(ratio, end_limit, basin_limit, work):
    beam = reference(ratio)
    check_steady_state(beam, ratio)
    ends, under, basin = measure(ratio, work, beam)
    print(f"v/v_cr = {ratio}: contact ends a1, a2, b1, b2 / l = "
          + ", ".join(f"{e / ELL:.4f}" for e in beam.x[4:])
          + f"; w under the load {beam.x[0]:.6e}")
    check(ends < end_limit, f"v/v_cr = {ratio}: contact ends off by "
          f"{ends:.2e} l (< {end_limit})")
    check(under < 1e-3, f"v/v_cr = {ratio}: w under the load off by "
          f"{under:.2e} (< 1e-3)")
    check(basin < basin_limit, f"v/v_cr = {ratio}: basin within 14 l off "
          f"by {basin:.2e} of w under the load (< {basin_limit})")


if __name__ == "__main__":
    strip.LIFTOFF = sys.argv[1]
    check_reference()
    with tempfile.TemporaryDirectory() as work:
        for ratio, end_limit, basin_limit in ((0.15, 0.01, 3e-3),
                                              (0.22, 0.1, 1e-2)):
            compare(ratio, end_limit, basin_limit, work)
    finish()
