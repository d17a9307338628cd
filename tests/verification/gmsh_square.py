#!/usr/bin/env python3
"""A gmsh mesh of the plate against the built-in rectangle: the same cells
read from tests/meshes/square.msh (Discretization/Shape = mesh file, made
by gmsh from square.geo) and made by GridGenerator (Shape = rectangle,
10 x 10 cells) must give the same history.csv to round-off:

  - free, dynamic: a sudden point load off the centre on a tensionless bed
    (lift-off in the first steps), 20 steps, probes inside and on the edge;
  - free, static: the same load and a pressure over the whole plate;
  - held by tags, static: West clamped, South soft and East hard simply
    supported (Boundary conditions/Mesh tags, by name and by number)
    against Left, Bottom and Right of the rectangle;
  - symmetry planes: the quarter [0, 1/2]^2 of tests/meshes/quarter.msh
    with its edges x = 0 and y = 0 held as symmetry planes and a quarter of
    the load, against the rectangle's Symmetry = quarter (probe columns
    only: the rectangle reports its energies for the full plate);
  - in SI units: tests/meshes/slab_5x3m.msh, a 5 m x 3 m slab in metres
    (Units/Length = 5, no Width), against the rectangle of Units/Length =
    5 and Width = 3 on 10 x 6 cells, a 50 kN force dropped on it; the
    columns are in metres, newtons and seconds.

Every column is compared relative to its largest magnitude (balance_error,
itself round-off, relative to the work); the limit is 1e-11. The meshes
are the same but for the last bit of some vertices (gmsh places x = -0.2
where GridGenerator computes -0.5 + 3 * 0.1 = -0.19999999999999996): the
dynamic run agrees to 2e-14, the static lift-off, five active-set solves
of a nearly singular free plate, to 3e-12.

    gmsh_square.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (point_load, pressure, read_history,  # noqa: E402
                    run_scene_or_fail, scene_text)

LIFTOFF = sys.argv[1]
MESHES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                      "meshes")
LIMIT = 1e-11
def scene(shape, analysis, *extra):
    """The scene on `shape` (entries of Discretization), with the EXTRA
    parts of scene_text."""
    return scene_text(
        {"Analysis": {"Type": analysis},
         "Plate": {"Thickness ratio": 0.05, "Poisson ratio": 0.3},
         "Foundation": {"Model": "tensionless", "Stiffness": 100},
         "Discretization": shape,
         "Time integration": {"Time step": 2e-3, "End time": 0.04},
         "Output": {"Probe points": "0.13, -0.07; 0, 0; 0.5, 0.5; "
                                    "-0.5, 0.2; 0.3, -0.5"}},
        point_load(1, 0.13, -0.07, 1), *extra)


def mesh(name):
    return {"Shape": "mesh file", "Mesh file": f"{MESHES}/{name}"}


# Down over most of the plate, up near the corner (1/2, 1/2), which
# lifts off.
PRESSURE = pressure(1, "if(x * y > 0.06, -3, 0.2)")


def si_scene(shape, units=None):
    """A concrete slab 5 m long in SI units on a tensionless bed, a 50 kN
    force dropped off its centre; `shape` and `units` are entries of
    Discretization and Units."""
    return scene_text(
        {"Units": {"System": "SI", "Length": 5, "Thickness": 0.25,
                   "Young's modulus": 30e9, "Density": 2400, "Gravity": 0,
                   "Subgrade modulus": 50e6, **(units or {})},
         "Plate": {"Poisson ratio": 0.2},
         "Foundation": {"Model": "tensionless"},
         "Discretization": shape,
         "Time integration": {"Time step": 2e-4, "End time": 4e-3},
         "Output": {"Probe points": "0.65, -0.35; 0, 0; 2.5, 1.5; "
                                    "-2.5, 0.5; 1.5, -1.5"}},
        point_load(1, 0.65, -0.35, 5e4))


def largest_difference(a, b, columns):
    """Largest difference of the columns relative to the column's largest
    magnitude (balance_error, itself round-off, relative to the work; both
    named with their unit in an SI run)."""
    work = next((c for c in a if c.split(" ")[0] == "work"), None)
    worst = 0.0
    for column in columns:
        scale = max(np.max(np.abs(
            a[work if column.startswith("balance_error") else column])),
            1e-300)
        worst = max(worst, np.max(np.abs(a[column] - b[column])) / scale)
    return worst


def compare(work, name, mesh_scene, rectangle_scene, probes_only=False):
    mesh = read_history(run_scene_or_fail(LIFTOFF, work, name + "_mesh",
                                          mesh_scene))
    rectangle = read_history(run_scene_or_fail(LIFTOFF, work,
                                               name + "_rectangle",
                                               rectangle_scene))
    same_columns = list(mesh) == list(rectangle)
    rows = len(next(iter(mesh.values())))  # of tau, or t [s] in SI
    check(same_columns and rows == len(next(iter(rectangle.values()))),
          f"{name}: the same columns and rows ({rows} rows)")
    columns = [c for c in rectangle if c.startswith("w(")] if probes_only \
        else list(rectangle)
    if not same_columns:
        return
    difference = largest_difference(rectangle, mesh, columns)
    check(difference < LIMIT,
          f"{name}: {len(columns)} columns, largest relative difference "
          f"{difference:.2e} < {LIMIT:.0e}")
    lifted = np.min(rectangle["contact_fraction"]) < 1
    check(lifted, f"{name}: the plate lifts off (contact fraction "
                  f"{np.min(rectangle['contact_fraction']):.3f})")


with tempfile.TemporaryDirectory() as work:
    square = mesh("square.msh")
    compare(work, "free_dynamic", scene(square, "dynamic"),
            scene({}, "dynamic"))
    compare(work, "free_static", scene(square, "static", PRESSURE),
            scene({}, "static", PRESSURE))
    held = {"Mesh tags": "West: clamped, 1: soft simply supported, "
                         "East: hard simply supported"}
    held_rectangle = {"Left": "clamped", "Bottom": "soft simply supported",
                      "Right": "hard simply supported"}
    compare(work, "held_static",
            scene(square, "static", PRESSURE, {"Boundary conditions": held}),
            scene({}, "static", PRESSURE,
                  {"Boundary conditions": held_rectangle}))
    compare(work, "si_metres", si_scene(mesh("slab_5x3m.msh")),
            si_scene({"Cells along x": 10, "Cells along y": 6},
                     {"Width": 3}))
    planes = {"Boundary conditions": {
        "Mesh tags": "Plane x: symmetry plane, Plane y: symmetry plane"}}
    centre_probes = {"Output": {
        "Probe points": "0, 0; 0.25, 0; 0.5, 0.5; 0.5, 0; 0.2, 0.3"}}
    compare(work, "symmetry_planes",
            scene(mesh("quarter.msh"), "dynamic", planes,
                  point_load(1, 0, 0, 0.25), centre_probes),
            scene({"Symmetry": "quarter"}, "dynamic",
                  point_load(1, 0, 0, 1), centre_probes), probes_only=True)

finish()
