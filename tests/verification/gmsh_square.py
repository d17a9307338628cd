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
from scenes import read_history, run_scene_or_fail  # noqa: E402

LIFTOFF = sys.argv[1]
MESHES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                      "meshes")
LIMIT = 1e-11
failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


def scene(shape, analysis, extra=""):
    """The scene on `shape` (the text of subsection Discretization)."""
    return f"""
subsection Analysis
  set Type = {analysis}
end
subsection Plate
  set Thickness ratio = 0.05
  set Poisson ratio = 0.3
end
subsection Foundation
  set Model = tensionless
  set Stiffness = 100
end
subsection Discretization
  set Polynomial degree = 2
{shape}
end
subsection Loads
  subsection Point load 1
    set Position = 0.13, -0.07
    set Magnitude = 1
  end
end
subsection Time integration
  set Time step = 2e-3
  set End time = 0.04
end
subsection Output
  set VTU interval = 0
  set Probe points = 0.13, -0.07; 0, 0; 0.5, 0.5; -0.5, 0.2; 0.3, -0.5
end
{extra}"""


MESH = f"  set Shape = mesh file\n  set Mesh file = {MESHES}/square.msh"
# Down over most of the plate, up near the corner (1/2, 1/2), which
# lifts off.
PRESSURE = """
subsection Loads
  subsection Pressure 1
    set Region = whole plate
    set Magnitude = 1
    set Intensity = if(x * y > 0.06, -3, 0.2)
  end
end
"""


def si_scene(shape, width=""):
    """A concrete slab 5 m long in SI units on a tensionless bed, a 50 kN
    force dropped off its centre; `shape` is the text of subsection
    Discretization, `width` a line of subsection Units."""
    return f"""
subsection Units
  set System = SI
  set Length = 5
{width}
  set Thickness = 0.25
  set Young's modulus = 30e9
  set Density = 2400
  set Gravity = 0
  set Subgrade modulus = 50e6
end
subsection Plate
  set Poisson ratio = 0.2
end
subsection Foundation
  set Model = tensionless
end
subsection Discretization
  set Polynomial degree = 2
{shape}
end
subsection Loads
  subsection Point load 1
    set Position = 0.65, -0.35
    set Magnitude = 5e4
  end
end
subsection Time integration
  set Time step = 2e-4
  set End time = 4e-3
end
subsection Output
  set VTU interval = 0
  set Probe points = 0.65, -0.35; 0, 0; 2.5, 1.5; -2.5, 0.5; 1.5, -1.5
end
"""


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
    compare(work, "free_dynamic", scene(MESH, "dynamic"),
            scene("", "dynamic"))
    compare(work, "free_static", scene(MESH, "static", PRESSURE),
            scene("", "static", PRESSURE))
    held = """
subsection Boundary conditions
  set Mesh tags = West: clamped, 1: soft simply supported, \\
                  East: hard simply supported
end
"""
    held_rectangle = """
subsection Boundary conditions
  set Left = clamped
  set Bottom = soft simply supported
  set Right = hard simply supported
end
"""
    compare(work, "held_static", scene(MESH, "static", PRESSURE + held),
            scene("", "static", PRESSURE + held_rectangle))
    quarter_mesh = f"""  set Shape = mesh file
  set Mesh file = {MESHES}/quarter.msh"""
    planes = """
subsection Boundary conditions
  set Mesh tags = Plane x: symmetry plane, Plane y: symmetry plane
end
"""
    quarter_load = """
subsection Loads
  subsection Point load 1
    set Position = 0, 0
    set Magnitude = 0.25
  end
end
subsection Output
  set Probe points = 0, 0; 0.25, 0; 0.5, 0.5; 0.5, 0; 0.2, 0.3
end
"""
    compare(work, "si_metres",
            si_scene(f"  set Shape = mesh file\n"
                     f"  set Mesh file = {MESHES}/slab_5x3m.msh"),
            si_scene("  set Cells along x = 10\n  set Cells along y = 6",
                     width="  set Width = 3"))
    compare(work, "symmetry_planes",
            scene(quarter_mesh, "dynamic", planes + quarter_load),
            scene("  set Symmetry = quarter", "dynamic",
                  quarter_load.replace("0.25\n", "1\n")), probes_only=True)

print(f"{failures} failure(s)")
sys.exit(1 if failures else 0)
