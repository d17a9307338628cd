#!/usr/bin/env python3
"""A joint's load transfer is the load's: the change of w since the plate
at rest, against a second run of the rest alone.

Two SI slabs on a tensionless bed, curled at night (a permanent dT of
-10 K) under their weight, with aggregate interlock; a two-wheel axle
crosses the joint (dynamic), or stands beside it (static). The same scene
without the axle is the rest: in a time integration it stays at its
settled state, in a static analysis it is the equilibrium under the weight
and the curl alone. The differences of w between the two runs at the joint
probe's two sides, and along the joint in joints.csv, give the load's
transfer (the smaller change over the larger) independently of liftoff's
own subtraction; lte(x;y), lte_x1 and joints.csv's lte must equal them.
Ratios of the total deflections (what liftoff wrote before) differ by 0.1
to 0.2 here (lte_x1 0.99 against 0.87 in the static case). Where the
larger change is below a tenth of the plate's largest, the load is far
and the ratio is written empty: the run without the axle has no load's
part at all, so every ratio of it is empty. No cell reads -0.

    joint_load_part.py LIFTOFF
"""

import csv
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (merged, prm_text, read_history,  # noqa: E402
                    run_scene_or_fail)

LIFTOFF = os.path.abspath(sys.argv[1])
PROBE = "(0;-1.8)"

SCENE = {
    "Units": {"System": "SI", "Length": 9, "Width": 3.6, "Thickness": 0.25,
              "Young's modulus": 30e9, "Density": 2400,
              "Subgrade modulus": 50e6, "Dashpot coefficient": 1.7e4},
    "Plate": {"Poisson ratio": 0.15},
    "Foundation": {"Model": "tensionless"},
    "Discretization": {"Cells along x": 18, "Cells along y": 8,
                       "Polynomial degree": 2},
    "Slabs": {"Slabs along x": 2, "Shear stiffness": 2e8},
    "Loads": {"Temperature load 1": {"Magnitude": -10,
                                     "Expansion coefficient": 1e-5,
                                     "Permanent": "true"}},
    "Time integration": {"Time step": 2e-3, "End time": 0.2},
    "Output": {"Joint probe points": "0, -1.8", "Joint profiles": "true",
               "Profile times": "0.1, 0.2", "VTU interval": 0},
}
AXLE = {"Loads": {"Vehicle 1": {
    "Magnitude": 80e3, "Wheels": "0, 0.9, 0.5; 0, -0.9, 0.5",
    "Wheel shape": "disc", "Wheel size": 0.3}}}


def ratio(a, b):
    """The smaller over the larger."""
    return a / b if abs(a) < abs(b) else b / a


def joints_csv(folder):
    """joints.csv's rows: (t, s) -> (w_lower, w_upper, lte or None)."""
    rows = {}
    with open(os.path.join(folder, "joints.csv")) as f:
        for row in csv.DictReader(f):
            lte = row["lte"]
            rows[(row["t [s]"], row["s [m]"])] = (
                float(row["w_lower [m]"]), float(row["w_upper [m]"]),
                float(lte) if lte else None)
    return rows


def no_negative_zero(folder):
    for name in ("history.csv", "joints.csv"):
        with open(os.path.join(folder, name)) as f:
            cells = [c for line in f for c in line.strip().split(",")]
        check("-0" not in cells, f"{os.path.basename(folder)}/{name}: no "
              f"cell reads -0")


def compare(work, name, changes, path):
    scene = merged(SCENE, changes)
    with_axle = merged(scene, merged(AXLE, {"Loads": {"Vehicle 1": {
        "Path": path}}}))
    loaded = run_scene_or_fail(LIFTOFF, work, name, prm_text(with_axle))
    rest = run_scene_or_fail(LIFTOFF, work, name + "-rest", prm_text(scene))
    h, h0 = read_history(loaded), read_history(rest)
    a = h["w_lower" + PROBE + " [m]"] - h0["w_lower" + PROBE + " [m]"]
    b = h["w_upper" + PROBE + " [m]"] - h0["w_upper" + PROBE + " [m]"]
    written = h["lte" + PROBE]
    given = ~np.isnan(written)
    expected = np.array([ratio(x, y) for x, y in zip(a[given], b[given])])
    error = np.max(np.abs(written[given] - expected), initial=0)
    check(given.sum() > 0 and error < 1e-8,
          f"{name}: lte{PROBE} is the load's part in {given.sum()} of "
          f"{len(given)} rows (largest difference {error:.1e})")
    total = np.array([ratio(x, y) for x, y in zip(
        h["w_lower" + PROBE + " [m]"], h["w_upper" + PROBE + " [m]"])])
    print(f"  {name}: ratio of totals differs by up to "
          f"{np.max(np.abs(total[given] - written[given])):.3f}")

    # lte_x1: at the point of the joint where a side's change is largest.
    profiles, profiles0 = joints_csv(loaded), joints_csv(rest)
    for t in sorted({key[0] for key in profiles}):
        changes_at = [(p[0] - profiles0[key][0], p[1] - profiles0[key][1],
                       p[2]) for key, p in profiles.items() if key[0] == t]
        worst = 0
        for da, db, lte in changes_at:
            if lte is not None:
                worst = max(worst, abs(lte - ratio(da, db)))
        check(worst < 1e-8, f"{name}: joints.csv's lte at t = {t} is the "
              f"load's part ({worst:.1e})")
        da, db, _ = max(changes_at, key=lambda c: max(abs(c[0]), abs(c[1])))
        row = np.argmin(np.abs(h["t [s]"] - float(t)))
        check(abs(h["lte_x1"][row] - ratio(da, db)) < 1e-8,
              f"{name}: lte_x1 at t = {t} ({h['lte_x1'][row]:.6f}) is the "
              f"load's part at the joint's most moved point "
              f"({ratio(da, db):.6f})")
    check(np.all(np.isnan(h0["lte_x1"])) and np.all(np.isnan(h0["lte" + PROBE])),
          f"{name}-rest: no load's part, every ratio empty")
    no_negative_zero(loaded)
    no_negative_zero(rest)


with tempfile.TemporaryDirectory() as work:
    compare(work, "dynamic", {}, "-3 + 20*t; -0.9")
    compare(work, "static", {"Analysis": {"Type": "static"}}, "-0.2; -0.9")
    # Far from the joint the ratio is empty, near it given.
    far = read_history(run_scene_or_fail(LIFTOFF, work, "far", prm_text(
        merged(merged(SCENE, AXLE), {"Loads": {"Vehicle 1": {
            "Path": "-4.4 + 20*t; -0.9"}}}))))
    check(np.isnan(far["lte_x1"][1]) and not np.isnan(far["lte_x1"][-1]),
          "an axle 4.4 m from the joint gives no ratio, at the joint one")
finish()
