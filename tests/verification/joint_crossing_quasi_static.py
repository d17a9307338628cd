#!/usr/bin/env python3
"""A load crossing a joint slowly against static runs at its positions.

Two slabs (joint x1 at x = 0) joined by aggregate interlock on a
bilateral bed with self-weight and dashpots (on a tensionless bed the
unloaded slab tilts off the bed and swings slowly, undamped, as a rigid
body: no speed of this test is slow against it); a point load ramped on at
x = -0.45 and moved across the joint at speed v. When the load stands at
x = -0.2, -0.05, 0.05 and 0.2, w at five probes (under those points and
beside the joint) is compared with static runs of the same scene with the
load at that point. The dynamic run lags the static one by the dashpots'
force c v dw/dx and by inertia ~ v^2, so its difference must shrink
with v: below 1 % of the largest |w| at v = 0.0125, and about halve when
v halves (ratio in [1.6, 2.6]). The stop 0.05 past the joint lies in the
ringing of the load's jump from one slab to the other, which decays over a
time, not a distance: at v = 0.1 it differed by 0.39 of the largest |w|
where the other stops differ by 0.03, at v = 0.05 by 0.027 against 0.016,
at 0.025 by 0.0094 against 0.0079 (the load on the joint at a step, half
on each side). So the speeds are 0.025 and 0.0125.

    joint_crossing_quasi_static.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

START = -0.45
STOPS = [-0.2, -0.05, 0.05, 0.2]
PROBES = "-0.2, 0; -0.05, 0; 0.05, 0; 0.2, 0; -0.01, 0.1"
BASE = {
    "Plate": {"Aspect ratio": 0.5, "Thickness ratio": 0.05},
    "Foundation": {"Model": "bilateral", "Stiffness": 500, "Damping": 10},
    "Discretization": {"Cells along x": 8, "Cells along y": 4},
    "Slabs": {"Slabs along x": 2, "Shear stiffness": 50},
    "Loads": {"Self weight": 5},
    "Output": {"Probe points": PROBES},
}


def static_at(work, x):
    folder = run_scene_or_fail(LIFTOFF, work, f"static_{x:g}", scene_text(
        BASE, {"Analysis": {"Type": "static"},
               "Loads": {"Point load 1": {"Magnitude": 300,
                                          "Position": f"{x:g}, 0"}}}))
    return read_history(folder)


def moving(work, v):
    end = (STOPS[-1] - START) / v
    folder = run_scene_or_fail(LIFTOFF, work, f"moving_{v:g}", scene_text(
        BASE, {"Loads": {"Point load 1": {
                   "Magnitude": 300, "Time history": "min(tau, 1)",
                   "Path": f"{START:g} + {v:g}*tau; 0"}},
               "Time integration": {"Time step": 0.02, "End time": end}}))
    return read_history(folder)


def largest_difference(statics, history, v):
    tau = history["tau"]
    worst, scale = 0.0, 0.0
    probes = [c for c in history if c.startswith("w(")]
    for x, static in zip(STOPS, statics):
        row = np.argmin(np.abs(tau - (x - START) / v))
        for c in probes:
            worst = max(worst, abs(history[c][row] - static[c][-1]))
            scale = max(scale, abs(static[c][-1]))
    return worst / scale


with tempfile.TemporaryDirectory() as work:
    statics = [static_at(work, x) for x in STOPS]
    errors = {v: largest_difference(statics, moving(work, v), v)
              for v in (0.025, 0.0125)}
    check(errors[0.0125] < 1e-2, f"v = 0.0125: w within "
          f"{errors[0.0125]:.2e} of the static runs' largest |w| at the "
          "four stops")
    ratio = errors[0.025] / errors[0.0125]
    check(1.6 < ratio < 2.6, f"v = 0.025: {errors[0.025]:.2e}, {ratio:.2f} "
          "times v = 0.0125's (the lag ~ v)")
finish()
