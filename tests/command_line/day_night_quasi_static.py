#!/usr/bin/env python3
"""prm/si-slab-day-night-truck.prm follows the static curled slab.

    day_night_quasi_static.py LIFTOFF

dT(t) rises from -10 to +10 K over 0.6 s, slow against the slab's bounce
on the bed (about 22 ms), so while the truck is off the slab the dynamic
run's contact fraction and centre deflection at a time t must be those of
a static run (the same scene, the truck off, dT(t) held as a permanent
load) at that dT. Compared at t = 0.1, 0.14 s (night, before the truck)
and 0.5, 0.6 s (day, after it); the tolerances are a few times the
differences measured (w within 0.55 % of the largest |w| and the
contact fraction within 0.007, both largest at t = 0.5 s, just after the
truck has left): centre deflection within 2 %, contact fraction within
0.02.
"""

import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
from liftoff_runs import read_csv, run_scene, scene_with_overrides  # noqa

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                     "prm", "si-slab-day-night-truck.prm")
TIMES = (0.1, 0.14, 0.5, 0.6)
W_TOLERANCE = 0.02
FRACTION_TOLERANCE = 0.02


def d_t(t):
    return -10 + 20 * (1 - math.cos(math.pi * t / 0.6)) / 2


def row_at(rows, t):
    return min(rows, key=lambda r: abs(r["t [s]"] - t))


def main(liftoff):
    folder = tempfile.mkdtemp(prefix="day_night_")
    run_scene(liftoff, scene_with_overrides(SCENE, [], folder + "/dynamic"),
              folder + "/dynamic")
    dynamic = read_csv(folder + "/dynamic/history.csv")
    failures = []
    for t in TIMES:
        static_dir = folder + "/static_%g" % t
        text = scene_with_overrides(SCENE, [
            "Loads/Temperature load 1/Magnitude=%r" % d_t(t),
            "Loads/Temperature load 2/Magnitude=0",
            "Loads/Vehicle 1/Magnitude=0",
            "Time integration/End time=0.004"], static_dir)
        run_scene(liftoff, text, static_dir)
        static = read_csv(static_dir + "/history.csv")[-1]
        moving = row_at(dynamic, t)
        scale = max(abs(static["w(0;0) [m]"]), abs(static["w(2.25;1.8) [m]"]))
        dw = abs(moving["w(0;0) [m]"] - static["w(0;0) [m]"]) / scale
        df = abs(moving["contact_fraction"] - static["contact_fraction"])
        print("t = %.2f s, dT = %+.2f K: w(0,0) %.4g (static %.4g) m, "
              "error %.2f %% of max |w|; contact %.4f (static %.4f)"
              % (t, d_t(t), moving["w(0;0) [m]"], static["w(0;0) [m]"],
                 100 * dw, moving["contact_fraction"],
                 static["contact_fraction"]))
        if dw > W_TOLERANCE or df > FRACTION_TOLERANCE:
            failures.append(t)
    if failures:
        sys.exit("day_night_quasi_static: the dynamic run leaves the static "
                 "curled slab at t = %s s" % failures)


if __name__ == "__main__":
    main(sys.argv[1])
