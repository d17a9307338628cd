#!/usr/bin/env python3
"""Slabs and joints from a mesh file (physical surfaces, curves of the
condition `joint`) against the same plate made another way:

  - two slabs: tests/meshes/two_slabs.msh, the square as two slabs meshed
    on their own and the physical curve Joint on x = 0 (given on both),
    against the rectangle's `Slabs along x = 2` on the same 10 x 10 cells
    (its joint x1): slabs of different thickness, a tensionless bed,
    self-weight, aggregate interlock and loose dowels (statuses changing),
    a load crossing the joint. Every history column, the joint's named
    x1 on one and Joint on the other, to 1e-9 of its largest value; on
    two ranks (a slab each) the same over 10 steps.
  - tied: tests/meshes/l_shaped_slabs.msh, prm/l-shaped-slab.geo's three
    blocks as three slabs with the joints J1 (x = 0) and J2 (y = 0), both
    tied, against the monolithic prm/l-shaped-slab.msh: every column to
    1e-9 (but the count of dofs, the joints' nodes counted once per slab).
  - equilibrium and symmetry: the same three slabs, free, with aggregate
    interlock on a bilateral bed and a pressure on slab A only: the bed's
    resultant equals the load, and as the L is symmetric about y = x (B
    the mirror image of C, here of the same thickness), the shear J1
    passes (a joint x = const) equals the shear J2 passes (y = const).

    mesh_joints.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (point_load, read_history, run_scene,  # noqa: E402
                    run_scene_or_fail, scene_text)

LIFTOFF = os.path.abspath(sys.argv[1])
HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = os.path.join(HERE, "..", "meshes")
PRM = os.path.join(HERE, "..", "..", "prm")
LIMIT = 1e-9


def largest_difference(a, b):
    """Largest difference of the columns of `a` and `b`, each relative to
    the column's largest magnitude in `a` (balance_error to the work)."""
    worst, where = 0.0, ""
    for column in a:
        scale = max(np.max(np.abs(
            a["work" if column == "balance_error" else column])), 1e-300)
        d = np.max(np.abs(a[column] - b[column])) / scale
        if d > worst:
            worst, where = d, column
    return worst, where


def compare(name, a, b, rows=None, skip=()):
    """Every column of `a` and `b` (their first `rows`) but `skip` to
    LIMIT."""
    if rows is not None:
        a = {c: v[:rows] for c, v in a.items()}
    a = {c: v for c, v in a.items() if c not in skip}
    b = {c: v for c, v in b.items() if c not in skip}
    same = list(a) == list(b) and len(a["tau"]) == len(b["tau"])
    check(same, f"{name}: the same {len(a)} columns and "
                f"{len(a['tau'])} rows")
    if same:
        d, where = largest_difference(a, b)
        check(d < LIMIT, f"{name}: largest relative difference {d:.2e} "
                         f"({where}) < {LIMIT:.0e}")


def two_slabs(shape, joint, end_time=0.06):
    slabs = {"Thicknesses": "0.05, 0.04", "Shear stiffness": 300,
             "Dowels": {"Joints": joint, "Spacing": 0.25,
                        "Stiffness": 200, "Looseness": 2e-4}}
    if shape == "rectangle":
        slabs["Slabs along x"] = 2
        discretization = {}
    else:
        discretization = {"Shape": "mesh file",
                          "Mesh file": f"{MESHES}/two_slabs.msh"}
    text = scene_text(
        {"Analysis": {"Type": "dynamic"},
         "Plate": {"Thickness ratio": 0.05, "Poisson ratio": 0.2},
         "Foundation": {"Model": "tensionless", "Stiffness": 100},
         "Discretization": discretization,
         "Boundary conditions": {"Mesh tags": "Joint: joint"}
         if shape != "rectangle" else {},
         "Slabs": slabs,
         "Loads": {"Self weight": 5,
                   "Point load 1": {"Magnitude": 300,
                                    # Never on the joint at a step: a
                                    # point there is on both slabs.
                                    "Path": "-0.31 + 6*tau; -0.2"}},
         "Time integration": {"Time step": 0.002, "End time": end_time},
         "Output": {"Probe points": "-0.1, -0.2; 0.1, -0.2; 0.4, 0.4",
                    "Write foundation resultant": "true"}})
    return text


def renamed(history, old, new):
    return {c.replace(old, new): v for c, v in history.items()}


def l_scene(mesh, tags, slabs, foundation, loads, analysis="dynamic"):
    return scene_text(
        {"Analysis": {"Type": analysis},
         "Plate": {"Thickness ratio": 0.05, "Poisson ratio": 0.2},
         "Foundation": foundation,
         "Discretization": {"Shape": "mesh file", "Mesh file": mesh},
         "Boundary conditions": {"Mesh tags": tags},
         "Slabs": slabs,
         "Loads": loads,
         "Time integration": {"Time step": 0.002, "End time": 0.03},
         "Output": {"Probe points": "-0.25, -0.25; 0.25, -0.25; "
                                    "-0.25, 0.25; -0.01, -0.01",
                    "Write foundation resultant": "true"}})


with tempfile.TemporaryDirectory() as work:
    rectangle = read_history(run_scene_or_fail(
        LIFTOFF, work, "rectangle", two_slabs("rectangle", "x1")))
    mesh = read_history(run_scene_or_fail(
        LIFTOFF, work, "mesh", two_slabs("mesh", "Joint")))
    check(np.min(rectangle["contact_fraction"]) < 1,
          f"two slabs: the plate lifts off (contact fraction down to "
          f"{np.min(rectangle['contact_fraction']):.3f})")
    compare("two slabs, mesh file against the rectangle",
            renamed(rectangle, "x1", "Joint"), mesh)
    folder, run = run_scene(LIFTOFF, work, "mesh_np2",
                            two_slabs("mesh", "Joint", 0.02), ranks=2)
    check(run.returncode == 0, "two slabs on 2 ranks: the run completes")
    if run.returncode == 0:
        # Where the bed presses most is a tie at rest (self-weight alone).
        compare("two slabs, 2 ranks against 1, 10 steps", mesh,
                read_history(folder), rows=11,
                skip=("max_pressure_x", "max_pressure_y"))

    wall = "Wall: soft simply supported"
    load = point_load(1, -0.1, -0.1, 1)["Loads"]
    tensionless = {"Model": "tensionless", "Stiffness": 300}
    monolithic = read_history(run_scene_or_fail(
        LIFTOFF, work, "l_monolithic",
        l_scene(f"{PRM}/l-shaped-slab.msh", wall, {}, tensionless, load)))
    tied = read_history(run_scene_or_fail(
        LIFTOFF, work, "l_tied",
        l_scene(f"{MESHES}/l_shaped_slabs.msh",
                wall + ", J1: joint, J2: joint",
                {"Tied joints": "J1, J2"}, tensionless, load)))
    # The tied slabs count the joints' nodes once per slab; their joints'
    # springs are a term of the system (its energy column) that holds
    # nothing.
    check(np.all(tied["joint_springs"] == 0),
          "L-shaped, tied joints: the joints' springs store nothing")
    compare("L-shaped, tied joints against the monolithic slab",
            monolithic, tied, skip=("dofs", "joint_springs"))

    pressure = {"Pressure 1": {"Region": "whole plate", "Magnitude": 2,
                               "Intensity": "if(x < 0 && y < 0, 1, 0)"}}
    joined = read_history(run_scene_or_fail(
        LIFTOFF, work, "l_joints",
        l_scene(f"{MESHES}/l_shaped_slabs.msh", "J1: joint, J2: joint",
                {"Shear stiffness": 50, "Thicknesses": "0.05, 0.04, 0.04"},
                {"Model": "bilateral", "Stiffness": 300}, pressure,
                "static")))
    load_on_a = 2 * 0.25
    resultant = joined["resultant"][-1]
    check(abs(resultant - load_on_a) < 1e-9 * load_on_a,
          f"L-shaped, three slabs: the bed's resultant {resultant:.12f} "
          f"equals the load {load_on_a}")
    j1, j2 = joined["shear_J1"][-1], joined["shear_J2"][-1]
    check(abs(j1) > 0.01 * load_on_a and abs(j1 - j2) < 1e-9 * abs(j1),
          f"L-shaped, three slabs: the joints pass {j1:.12f} and "
          f"{j2:.12f}, equal by symmetry")
    finish()
