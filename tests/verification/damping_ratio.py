#!/usr/bin/env python3
"""The bed's dashpots given as a share of their critical value
(Foundation/Damping ratio): a free plate on a bilateral bed, let go from a
uniform deflection, bounces as a rigid body, w'' + 2 zeta omega w' +
omega^2 w = 0 with omega = sqrt(Gamma) (unit mass per area):

- w follows the scalar Newmark recursion of that oscillator (average
  acceleration), written out here, to round-off, at zeta = 0.05 and 0.2;
- the logarithmic decrement between successive peaks of w is the closed
  form 2 pi zeta / sqrt(1 - zeta^2) (to the time step's error);
- an SI scene with Damping ratio equals the one with Units/Dashpot
  coefficient = zeta 2 sqrt(k rho H).

    damping_ratio.py LIFTOFF
"""

import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

GAMMA, W0, DT, END = 400.0, 1.0, 0.0025, 2.0
BOUNCE = {
    "Plate": {"Thickness ratio": 0.05},
    "Foundation": {"Model": "bilateral", "Stiffness": GAMMA},
    "Discretization": {"Cells along x": 2, "Cells along y": 2},
    "Initial conditions": {"Displacement": f"{W0}; 0; 0"},
    "Time integration": {"Time step": DT, "End time": END},
    "Output": {"Probe points": "0.3, -0.2"},
}


def newmark(zeta, n):
    """Average acceleration for w'' + 2 zeta omega w' + omega^2 w = 0."""
    omega = math.sqrt(GAMMA)
    c, k = 2 * zeta * omega, omega ** 2
    u, v = W0, 0.0
    a = -k * u
    w = [u]
    for _ in range(n):
        a1 = -(c * (v + 0.5 * DT * a) + k * (u + DT * v + 0.25 * DT ** 2 * a)) \
            / (1 + 0.5 * DT * c + 0.25 * DT ** 2 * k)
        u, v = u + DT * v + 0.25 * DT ** 2 * (a + a1), v + 0.5 * DT * (a + a1)
        a = a1
        w.append(u)
    return np.array(w)


def peaks(w):
    """The maxima of w by a parabola through each discrete maximum and its
    neighbours."""
    values = []
    for i in range(1, len(w) - 1):
        if w[i] > w[i - 1] and w[i] >= w[i + 1] and w[i] > 0:
            a, b, c = w[i - 1], w[i], w[i + 1]
            values.append(b - (a - c) ** 2 / (8 * (a - 2 * b + c)))
    return np.array(values)


def bounce(work, zeta):
    history = read_history(run_scene_or_fail(
        LIFTOFF, work, f"zeta_{zeta:g}",
        scene_text(BOUNCE, {"Foundation": {"Damping ratio": zeta}})))
    w = history["w(0.3;-0.2)"]
    reference = newmark(zeta, len(w) - 1)
    error = np.max(np.abs(w - reference)) / W0
    check(error < 1e-9, f"zeta = {zeta:g}: w against Newmark's recursion "
          f"for c = 2 zeta sqrt(Gamma): {error:.1e} of w0")
    top = peaks(w)
    decrement = np.log(top[:-1] / top[1:])
    closed = 2 * math.pi * zeta / math.sqrt(1 - zeta ** 2)
    spread = np.max(np.abs(decrement - closed)) / closed
    check(len(top) >= 3 and spread < 2e-3,
          f"zeta = {zeta:g}: log decrement over {len(top) - 1} periods "
          f"{np.mean(decrement):.6f} against 2 pi zeta / sqrt(1 - zeta^2) = "
          f"{closed:.6f} (largest relative difference {spread:.1e})")


def si_twin(work):
    rho, h, k, zeta = 2400.0, 0.25, 50e6, 0.1
    base = {"Units": {"System": "SI", "Length": 4, "Thickness": h,
                      "Young's modulus": 30e9, "Density": rho,
                      "Gravity": 0, "Subgrade modulus": k},
            "Foundation": {"Model": "bilateral"},
            "Discretization": {"Cells along x": 2, "Cells along y": 2},
            "Initial conditions": {"Displacement": "0.001; 0; 0"},
            "Time integration": {"Time step": 2e-4, "End time": 0.02},
            "Output": {"Probe points": "0.5, 0.5"}}
    by_ratio = read_history(run_scene_or_fail(LIFTOFF, work, "si_ratio",
                                              scene_text(base, {
        "Foundation": {"Damping ratio": zeta}})))
    dashpot = zeta * 2 * math.sqrt(k * rho * h)
    by_dashpot = read_history(run_scene_or_fail(LIFTOFF, work, "si_dashpot",
                                                scene_text(base, {
        "Units": {"Dashpot coefficient": f"{dashpot:.17g}"}})))
    a, b = by_ratio["w(0.5;0.5) [m]"], by_dashpot["w(0.5;0.5) [m]"]
    error = np.max(np.abs(a - b)) / np.max(np.abs(b))
    check(error < 1e-12, f"SI: Damping ratio {zeta} against Dashpot "
          f"coefficient {dashpot:.6g} Pa s/m = zeta 2 sqrt(k rho H): "
          f"relative difference {error:.1e}")


with tempfile.TemporaryDirectory() as work:
    for zeta in (0.05, 0.2):
        bounce(work, zeta)
    si_twin(work)
finish()
