#!/usr/bin/env python3
"""Slabs of given lengths and widths (Slabs/Slab lengths, Slab widths)
against each slab alone, and against their mirror image:

- a 10 x 4.8 m pavement as slabs of 4.5 and 5.5 m along x and a 1.2 m
  shoulder beside a 3.6 m lane along y, the joints free, on a bilateral
  bed (static): a free joint passes nothing, so the loaded slab (4.5 m by
  3.6 m) deflects as a plate of that size alone (its own scene, the same
  cells), at probes near its four edges, and the slabs beside it do not
  move. A joint anywhere else makes the loaded slab another size;
- the same lengths mirrored (5.5, 4.5) under the mirrored load give the
  mirrored deflections, with a joint that passes shear (Shear stiffness).

    unequal_slabs.py LIFTOFF
"""

import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

SI = {
    "Units": {"System": "SI", "Thickness": 0.25, "Young's modulus": 30e9,
              "Density": 2400, "Gravity": 0, "Subgrade modulus": 50e6},
    "Plate": {"Poisson ratio": 0.15},
    "Foundation": {"Model": "bilateral"},
    "Analysis": {"Type": "static"},
}
# The loaded slab: x in [-5, -0.5], y in [-1.2, 2.4] of the pavement.
CENTRE = (-2.75, 0.6)
LOAD = (-1.2, 1.5)
PROBES = [(-0.55, 1.5), (-4.9, 0.0), (-1.2, -1.1), (-1.2, 2.3), (-2.0, 0.3)]
OTHERS = [(-0.45, 1.5), (-1.2, -1.3)]


def points(ps, shift=(0.0, 0.0)):
    return "; ".join(f"{x - shift[0]:.6g}, {y - shift[1]:.6g}" for x, y in ps)


def quantities(ps, shift=(0.0, 0.0)):
    return ", ".join(f"{q}({x - shift[0]:.6g}; {y - shift[1]:.6g})"
                     for q in ("M_xx", "M_yy") for x, y in ps)


def alone(work):
    jointed = read_history(run_scene_or_fail(LIFTOFF, work, "jointed",
                                             scene_text(SI, {
        "Units": {"Length": 10, "Width": 4.8},
        "Discretization": {"Cells along x": 20, "Cells along y": 8},
        "Slabs": {"Slab lengths": "4.5, 5.5", "Slab widths": "1.2, 3.6"},
        "Loads": {"Point load 1": {"Magnitude": 50e3,
                                   "Position": points([LOAD])}},
        "Output": {"Probe points": points(PROBES + OTHERS),
                   "Probe quantities": quantities(PROBES)}})))
    single = read_history(run_scene_or_fail(LIFTOFF, work, "alone",
                                            scene_text(SI, {
        "Units": {"Length": 4.5, "Width": 3.6},
        "Discretization": {"Cells along x": 9, "Cells along y": 6},
        "Loads": {"Point load 1": {"Magnitude": 50e3,
                                   "Position": points([LOAD], CENTRE)}},
        "Output": {"Probe points": points(PROBES, CENTRE),
                   "Probe quantities": quantities(PROBES, CENTRE)}})))
    mine = [c for c in jointed if c.split("(")[0] in ("w", "M_xx", "M_yy")]
    theirs = [c for c in single if c.split("(")[0] in ("w", "M_xx", "M_yy")]
    compared = list(zip([c for c in mine if not any(
        f"({x:.6g};{y:.6g})" in c for x, y in OTHERS)], theirs))
    check(len(compared) == 3 * len(PROBES), f"{len(compared)} probe columns "
          f"of the loaded slab ({3 * len(PROBES)})")
    for a, b in compared:
        scale = max(abs(single[b][-1]), 1e-300)
        error = abs(jointed[a][-1] - single[b][-1]) / scale
        check(error < 1e-9, f"slab 4.5 x 3.6 m in the pavement: {a} "
              f"against alone {b}: relative difference {error:.1e}")
    w_load = abs(jointed[mine[0]][-1])
    for x, y in OTHERS:
        column = next(c for c in jointed if c.startswith(f"w({x:.6g};{y:.6g})"))
        w = abs(jointed[column][-1])
        check(w < 1e-12 * w_load, f"{column} across a free joint: "
              f"{w:.1e} (the load's slab {w_load:.2e})")


def mirrored(work):
    def scene(name, lengths, sign):
        return read_history(run_scene_or_fail(LIFTOFF, work, name, scene_text(
            SI, {"Units": {"Length": 10, "Width": 4.8},
                 "Discretization": {"Cells along x": 20, "Cells along y": 8},
                 "Slabs": {"Slab lengths": lengths, "Slab widths": "1.2, 3.6",
                           "Shear stiffness": 5e8},
                 "Loads": {"Point load 1": {
                     "Magnitude": 50e3,
                     "Position": points([(sign * LOAD[0], LOAD[1])])}},
                 "Output": {"Probe points": points(
                     [(sign * x, y) for x, y in PROBES + OTHERS])}})))
    left = scene("left", "4.5, 5.5", 1)
    right = scene("right", "5.5, 4.5", -1)
    columns = [c for c in left if c.startswith("w(")]
    scale = max(abs(left[c][-1]) for c in columns)
    error = max(abs(left[a][-1] - right[b][-1])
                for a, b in zip(columns, [c for c in right
                                          if c.startswith("w(")])) / scale
    check(len(columns) == 7 and error < 1e-9,
          f"slabs 4.5, 5.5 against 5.5, 4.5 mirrored, joints with shear: "
          f"w at {len(columns)} mirrored probes, relative difference "
          f"{error:.1e}")
    share = max(abs(left[c][-1]) for c in columns if "(-0.45;1.5)" in c)
    check(share > 1e-3 * scale, f"the joint passes shear: w across it "
          f"{share / scale:.2f} of the largest")


with tempfile.TemporaryDirectory() as work:
    alone(work)
    mirrored(work)
finish()
