#!/usr/bin/env python3
"""Joints on and across the symmetry planes against the full plate, and a
line load along joints against the plate without them:

- four slabs along x and two along y (joints x1, x3 off the planes, x2 on
  x = 0, y1 on y = 0) with aggregate interlock and a rotational stiffness,
  on a tensionless bed, under loads symmetric about both axes (point
  loads, a line along x2): the half model (x2 on its plane, y1 across it)
  and the quarter model (both on planes) against the full plate, every
  column of history.csv, joint probes included. On a plane the other
  side of a joint is the mirror image: [w] = 0 and [psi . n] = 2 psi . n,
  so the joint passes no shear and its rotational springs act with 2 R
  on the modelled side;
- the same with point loads on the joints that lie on the planes (half
  to each side);
- the same with lists of stiffnesses per joint of the whole plate (the
  half and quarter models take their joints' values from them);
- the same with x2 and y1 tied (a tied joint on a plane is the plane);
- a line load along the joints of four slabs, all tied and all stiff,
  against the same line on the plate without joints: each slab carries
  half of a line along its joint face.

    symmetric_joints.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (point_load, read_history, run_scene_or_fail,  # noqa: E402
                    scene_text)

LIFTOFF = os.path.abspath(sys.argv[1])

BASE = {
    "Discretization": {"Polynomial degree": 1},
    "Slabs": {"Slabs along x": 4, "Slabs along y": 2,
              "Shear stiffness": 50, "Rotational stiffness": 3},
    "Foundation": {"Model": "tensionless"},
    "Time integration": {"Time step": 1e-3, "End time": 0.01},
    "Loads": {"Line load 1": {"Magnitude": 2,
                              "Segment": "0, -0.2, 0, 0.2"}},
    "Output": {"Probe points": "0.3, 0.3; 0.01, 0.2; 0.2, 0.01; 0.45, 0.1",
               "Joint probe points": "0, 0.3; 0.3, 0; 0.25, 0.2"},
}
LOADS = {}
for k, (x, y) in enumerate([(0.2, 0.1), (-0.2, 0.1), (0.2, -0.1),
                            (-0.2, -0.1)]):
    LOADS = {"Loads": {**LOADS.get("Loads", {}),
                       **point_load(k + 1, x, y, 1)["Loads"]}}
CELLS = {"full": (8, 8), "half": (4, 8), "quarter": (4, 4)}
SKIPPED = ("cells", "dofs", "balance_error")


def compare(full, part, what, tolerance=1e-10, least=20):
    """Every column of FULL that PART has, against PART; the shear of a
    joint on a plane is round-off on both, compared absolutely."""
    compared = 0
    for column, values in full.items():
        if column in SKIPPED or column not in part:
            continue
        scale = np.max(np.abs(values))
        if column.startswith("shear_"):
            scale = max(scale, 1.0)
        error = np.max(np.abs(values - part[column])) / max(scale, 1e-300)
        if error >= tolerance:
            check(False, f"{what}: {column} differs by {error:.1e}")
        compared += 1
    check(compared >= least, f"{what}: {compared} columns agree within "
          f"{tolerance:g}")


def symmetric_parts(work, name, extra, per_model=None, loads=None,
                    models=("full", "half", "quarter"), tolerance=1e-10):
    runs = {}
    for symmetry in models:
        nx, ny = CELLS[symmetry]
        runs[symmetry] = read_history(run_scene_or_fail(
            LIFTOFF, work, f"{name}-{symmetry}", scene_text(
                BASE, loads or LOADS, extra,
                (per_model or {}).get(symmetry, {}),
                {"Discretization": {"Symmetry": symmetry,
                                    "Cells along x": nx,
                                    "Cells along y": ny}})))
    for symmetry in models[1:]:
        compare(runs["full"], runs[symmetry], f"{name}, {symmetry} model",
                tolerance)
    return runs["full"]


def line_along_joints(work):
    line = {"Loads": {"Line load 1": {"Magnitude": 2,
                                      "Segment": "0, -0.4, 0, 0.4"},
                      "Line load 2": {"Magnitude": 1,
                                      "Segment": "-0.3, 0, 0.3, 0"}},
            "Discretization": {"Cells along x": 8, "Cells along y": 8},
            "Output": {"Probe points": "0.1, 0.1; 0.3, -0.2"}}
    plain = {k: v for k, v in BASE.items() if k != "Slabs"}
    plain["Output"] = {}
    alone = read_history(run_scene_or_fail(
        LIFTOFF, work, "line-plain", scene_text(plain, line)))
    slabs = {"Slabs": {"Slabs along x": 2, "Slabs along y": 2}}
    tied = read_history(run_scene_or_fail(
        LIFTOFF, work, "line-tied", scene_text(
            plain, line, slabs, {"Slabs": {"Tied joints": "x1, y1"}})))
    compare(alone, tied, "lines along tied joints", 1e-11, 10)
    stiff = read_history(run_scene_or_fail(
        LIFTOFF, work, "line-stiff", scene_text(
            plain, line, slabs, {"Slabs": {"Shear stiffness": 1e8,
                                           "Rotational stiffness": 1e6}})))
    error = (np.max(np.abs(alone["w(0.1;0.1)"] - stiff["w(0.1;0.1)"]))
             / np.max(np.abs(alone["w(0.1;0.1)"])))
    check(error < 1e-4, f"lines along stiff joints: w(0.1;0.1) within "
          f"{error:.1e} of the plate without joints")


with tempfile.TemporaryDirectory() as work:
    full = symmetric_parts(work, "springs", {})
    # Row 0 is the rest, with no load's part to transfer (empty).
    check(np.max(np.abs(full["lte_x2"][1:] - 1)) < 1e-12
          and np.max(np.abs(full["shear_x2"])) < 1e-12,
          f"the full plate's x2 passes no shear (largest "
          f"{np.max(np.abs(full['shear_x2'])):.1e}), LTE 1")
    check(np.max(np.abs(full["shear_x1"])) > 1e-3,
          f"x1, off the planes, passes shear (largest "
          f"{np.max(np.abs(full['shear_x1'])):.3e})")
    # Point loads on the joints on the planes (x2 on x = 0, y1 on y = 0):
    # half to each side, as the mirror image takes half on a plane (before,
    # the full plate gave the whole load to the slab whose cell came first).
    on_joints = {"Loads": {**LOADS["Loads"]}}
    for k, (x, y) in enumerate([(0, 0.15), (0, -0.15), (0.3, 0), (-0.3, 0)]):
        on_joints["Loads"].update(point_load(5 + k, x, y, 0.5)["Loads"])
    symmetric_parts(work, "on-joints", {}, loads=on_joints)
    # Lists per joint of the whole plate (x1, x2, x3, y1), as Thicknesses
    # counts slabs, on every model: x1 and x3 mirror each other.
    symmetric_parts(work, "lists", {"Slabs": {
        "Shear stiffness": "40, 70, 40, 20",
        "Rotational stiffness": "2, 5, 2, 1"}})
    symmetric_parts(work, "tied", {"Slabs": {"Tied joints": "x2, y1"},
                                   "Output": {"Joint probe points":
                                              "0.25, 0.2"}})
    # Loose dowels on x2 (on x = 0) and x3 (across y = 0, with a dowel on
    # that plane, half of it in the quarter model).
    along = {"x1": "0.2, 0.5, 0.8", "x2": "0.25, 0.75", "x3": "0.2, 0.5, 0.8"}
    dowels = {"Slabs": {"Slabs along y": 1,
                        "Dowels": {"Stiffness": 30, "Looseness": 2e-4}},
              "Output": {"Joint probe points": "0, 0.3; 0.25, 0.2"}}
    joints = {"full": ["x1", "x2", "x3"], "half": ["x2", "x3"],
              "quarter": ["x2", "x3"]}
    named = {symmetry: {"Slabs": {"Dowels": {
        "Joints": ", ".join(names),
        "Positions": "; ".join(f"{n}: {along[n]}" for n in names)}}}
        for symmetry, names in joints.items()}
    # Measured 4.2e-10 at most (the springs alone: 1e-12).
    full = symmetric_parts(work, "dowels", dowels, named, tolerance=1e-9)
    forces = [c for c in full if c.startswith("dowel_")]
    check(len(forces) == 8 and np.max(np.abs(full["dowel_x3_2"])) > 1e-3,
          f"{len(forces)} dowels, the one on x3 at y = 0 passing "
          f"{np.max(np.abs(full['dowel_x3_2'])):.3e}")
    # Slabs above and below y1, loads above it: y1's dowels pass forces,
    # the one on x = 0 half of it in the half model.
    above = {"Loads": {k: v for k, v in LOADS["Loads"].items()
                       if k in ("Point load 1", "Point load 2")}}
    full = symmetric_parts(
        work, "dowels-above",
        {"Slabs": {"Slabs along x": 1,
                   "Dowels": {"Stiffness": 30, "Looseness": 5e-5,
                              "Joints": "y1", "Positions": "0.1, 0.5, 0.9"}},
         "Output": {"Joint probe points": "0.3, 0"}},
        loads=above, models=("full", "half"), tolerance=1e-9)
    check(np.max(np.abs(full["dowel_y1_2"])) > 1e-3,
          f"the dowel on y1 at x = 0 passes "
          f"{np.max(np.abs(full['dowel_y1_2'])):.3e}")
    line_along_joints(work)
finish()
