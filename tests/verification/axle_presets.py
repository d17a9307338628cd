#!/usr/bin/env python3
"""A vehicle given as axle groups (Loads/Vehicle n/Axles) against the
geometry it declares, computed here:

- equilibrium: on a free plate on a bilateral bed (static), the bed's
  resultant equals the sum of the axle loads and its centre is their
  centre, with the tyres placed from Group spacings, Axle spacing, Track
  width and Dual spacing as this test places them;
- tyre positions and contact areas: the preset (a tandem on dual tyres and
  an aircraft's tridem gear) against the same tyres typed wheel by wheel
  (Wheels) at the positions computed here, discs of area load / pressure,
  and PCA's rectangles 0.8712 l x 0.6 l of that area: the deflections at
  the tyres' centres and between them agree to round-off;
- the aircraft gears of prm/gears/, included in a vehicle: the same
  against their data read here (spacings, pressure, load per axle);
- the direction of travel: the preset driven along y (discs and PCA's
  rectangles, turned a quarter) and along a diagonal (discs) against its
  tyres typed at the declared geometry turned here to the path's
  direction, the front ahead and the first tyre of an axle on the
  vehicle's left.

    axle_presets.py LIFTOFF
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

PRESSURE = 0.7e6
TRACK, DUAL, AXLE = 1.8, 0.34, 1.3
BASE = {
    "Units": {"System": "SI", "Length": 12, "Width": 6, "Thickness": 0.25,
              "Young's modulus": 30e9, "Density": 2400,
              "Gravity": 0, "Subgrade modulus": 50e6},
    "Plate": {"Poisson ratio": 0.15},
    "Foundation": {"Model": "bilateral"},
    "Analysis": {"Type": "static"},
    "Discretization": {"Cells along x": 24, "Cells along y": 12},
    "Output": {"Write foundation resultant": "true"},
}


def tyres(groups, spacings, track=TRACK, dual=DUAL, axle=AXLE):
    """(dx, dy, force) of each tyre: GROUPS of (n axles, tyres, load per
    axle), the first group's middle at the path's point, the others
    SPACINGS behind, as the documentation of Axles places them."""
    across = {"single": [track / 2, -track / 2],
              "dual": [track / 2 + dual / 2, track / 2 - dual / 2,
                       -track / 2 + dual / 2, -track / 2 - dual / 2],
              "gear": [dual / 2, -dual / 2]}
    result, middle = [], 0.0
    for g, (n, kind, load) in enumerate(groups):
        middle -= spacings[g - 1] if g > 0 else 0.0
        for a in range(n):
            x = middle + ((n - 1) / 2 - a) * axle
            result += [(x, y, load / len(across[kind])) for y in across[kind]]
    return result


def axles_text(groups):
    names = {1: "single", 2: "tandem", 3: "tridem"}
    return "; ".join(f"{names[n]}, {kind}, {load:g}" for n, kind, load in groups)


def equilibrium(work):
    groups = [(1, "single", 50e3), (2, "dual", 80e3)]
    path = (3.0, 0.4)
    history = read_history(run_scene_or_fail(LIFTOFF, work, "equilibrium",
                                             scene_text(BASE, {"Loads": {
        "Vehicle 1": {"Axles": axles_text(groups), "Group spacings": 5,
                      "Tyre pressure": PRESSURE, "Wheel shape": "disc",
                      "Path": f"{path[0]}; {path[1]}"}}})))
    placed = np.array(tyres(groups, [5.0]))
    total = placed[:, 2].sum()
    check(abs(total - 210e3) < 1e-9, f"the tyres carry the axle loads, "
          f"{total:.6g} N = 50 + 2 x 80 kN")
    resultant = history["resultant [N]"][-1]
    check(abs(resultant - total) < 1e-9 * total,
          f"bed resultant {resultant:.10g} N against the axle loads "
          f"{total:.10g} N")
    for column, k, origin in (("resultant_x [m]", 0, path[0]),
                              ("resultant_y [m]", 1, path[1])):
        centre = origin + (placed[:, k] * placed[:, 2]).sum() / total
        value = history[column][-1]
        check(abs(value - centre) < 1e-8, f"{column} {value:.9f} against "
              f"the tyres' centre {centre:.9f}")


def turned(placed, heading):
    """PLACED tyres (dx forward, dy to the left, force) in the plate's axes
    for a vehicle that heads along the unit vector HEADING."""
    hx, hy = heading
    return [(dx * hx - dy * hy, dx * hy + dy * hx, f) for dx, dy, f in placed]


def against_wheels(work, shape, groups=((2, "dual", 80e3), (3, "gear", 40e3)),
                   gear=None, spacing=(DUAL, AXLE), pressure=PRESSURE,
                   heading=(1.0, 0.0), base=BASE, path=(2.5, -0.3)):
    """The preset against its tyres typed as Wheels (all carry the same
    load); `gear`: a file of prm/gears/ that gives the preset; `heading`:
    the direction of the path (the static run is at its start, t = 0)."""
    placed = turned(tyres(groups, [4.0], dual=spacing[0], axle=spacing[1]),
                    heading)
    force = placed[0][2]
    area = force / pressure
    if shape == "disc":
        size = f"{math.sqrt(4 * area / math.pi):.17g}"
    else:
        side = math.sqrt(area / (0.8712 * 0.6))
        sides = (0.8712 * side, 0.6 * side)
        if abs(heading[1]) == 1:
            sides = sides[::-1]
        size = f"{sides[0]:.17g}, {sides[1]:.17g}"
    probes = [(path[0] + dx, path[1] + dy) for dx, dy, _ in placed[::3]]
    probes += [(path[0] - 0.65, path[1]), (path[0] - 4, path[1] + 0.5)]
    output = {"Probe points": "; ".join(f"{x:.6f}, {y:.6f}"
                                        for x, y in probes)}
    vehicle = {"Axles": axles_text(groups), "Group spacings": 4,
               "Tyre pressure": pressure}
    if gear is not None:
        vehicle = {"GEAR": gear}
    moving = f"{path[0]} + {heading[0]}*t; {path[1]} + {heading[1]}*t"
    text = scene_text(base, {"Loads": {"Vehicle 1": {
        **vehicle, "Wheel shape": shape, "Path": moving}},
        "Output": output}).replace("set GEAR =", "include")
    name = shape + ("" if gear is None else "_" + os.path.basename(gear))
    name += "" if heading == (1.0, 0.0) else f"_heading_{heading[0]}_{heading[1]}"
    preset = read_history(run_scene_or_fail(LIFTOFF, work, "preset_" + name,
                                            text))
    typed = read_history(run_scene_or_fail(LIFTOFF, work, "typed_" + name,
                                           scene_text(base, {
        "Loads": {"Vehicle 1": {
            "Magnitude": force,
            "Wheels": "; ".join(f"{dx:.17g}, {dy:.17g}, 1"
                                for dx, dy, _ in placed),
            "Wheel shape": shape, "Wheel size": size,
            "Path": moving}},
        "Output": output})))
    columns = [c for c in preset if c.startswith("w(")]
    scale = max(abs(preset[c][-1]) for c in columns)
    error = max(abs(preset[c][-1] - typed[c][-1]) for c in columns) / scale
    check(len(columns) == len(probes) and error < 1e-10,
          f"{name}: w at {len(columns)} probes (tyre centres, between "
          f"groups) against the tyres typed at the declared spacings, "
          f"contact area load / pressure: relative difference {error:.1e}")
    load = preset["resultant [N]"][-1]
    check(abs(load - force * len(placed)) < 1e-9 * load,
          f"{name}: bed resultant {load:.10g} N = {len(placed)} tyres x "
          f"{force:g} N")


def gears(work):
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                          "..", "prm", "gears")
    for name in sorted(os.listdir(folder)):
        data = {}
        with open(os.path.join(folder, name)) as f:
            for line in f:
                if line.startswith("set "):
                    key, value = line[4:].split("=", 1)
                    data[key.strip()] = value.strip()
        kind, tyres_, load = [v.strip() for v in data["Axles"].split(",")]
        n = {"single": 1, "tandem": 2, "tridem": 3}[kind]
        against_wheels(work, "disc", [(n, tyres_, float(load))],
                       os.path.join(folder, name),
                       (float(data["Dual spacing"]),
                        float(data.get("Axle spacing", AXLE))),
                       float(data["Tyre pressure"]))


def headings(work):
    """A lane along y (the vehicle heads -y, so its left is +x) and a
    diagonal, on a square plate that holds the turned vehicle."""
    square = {**BASE, "Units": {**BASE["Units"], "Width": 12},
              "Discretization": {"Cells along x": 24, "Cells along y": 24}}
    for shape in ("disc", "rectangle"):
        against_wheels(work, shape, heading=(0.0, -1.0), base=square,
                       path=(-0.4, -2.5))
    against_wheels(work, "disc", heading=(0.6, 0.8), base=square,
                   path=(2.0, 2.5))


with tempfile.TemporaryDirectory() as work:
    equilibrium(work)
    against_wheels(work, "disc")
    against_wheels(work, "rectangle")
    gears(work)
    headings(work)
finish()
