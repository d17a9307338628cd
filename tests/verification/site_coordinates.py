#!/usr/bin/env python3
"""A mesh in site coordinates gives the answer of the same mesh at the
origin (issue 46, finding 5): the plate's answer cannot depend on where
its coordinates start.

A 4 m x 2 m slab of one Q2 cell, written by this test as a msh 2.2 file
with its corner at (0, 0) and at (1e5, 1e5) m, in an SI scene (Length
4 m, 0.25 m of concrete, bilateral bed 50 MPa/m), 50 kN at its middle:
 - static: every column of history.csv (the resultant, its centre taken
   relative to the slab's corner, w at the middle and a corner) of the
   shifted slab against the slab at the origin, within 1e-9 of each
   column's largest magnitude (balance_error, round-off, of the work's;
   not the point of the largest pressure, which round-off picks among
   equal pressures at mirror Gauss points);
 - dynamic, with self-weight (the settling solve before the time loop):
   the same, 10 steps.
The rigid-body check of the free slab took moments about the origin: at
1e5 m the modes 1, x and y were parallel to round-off and the slab was
refused as lifting off everywhere ("Give it a foundation" in dynamics).

    site_coordinates.py LIFTOFF
"""

import json
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene, scene_text  # noqa: E402

LIFTOFF = sys.argv[1]
SHIFT = 1e5
LIMIT = 1e-9


def write_mesh(path, x0, y0):
    """One quadrilateral [x0, x0 + 4] x [y0, y0 + 2] in metres."""
    corners = [(x0, y0), (x0 + 4, y0), (x0 + 4, y0 + 2), (x0, y0 + 2)]
    nodes = "\n".join(f"{i + 1} {x!r} {y!r} 0"
                      for i, (x, y) in enumerate(corners))
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                f"$Nodes\n4\n{nodes}\n$EndNodes\n"
                "$Elements\n1\n1 3 2 1 1 1 2 3 4\n$EndElements\n")


def scene(mesh, x0, y0, analysis, gravity):
    middle, corner = (x0 + 2, y0 + 1), (x0 + 4, y0 + 2)
    return scene_text(
        {"Analysis": {"Type": analysis},
         "Units": {"System": "SI", "Length": 4, "Thickness": 0.25,
                   "Young's modulus": 30e9, "Density": 2400,
                   "Gravity": gravity, "Subgrade modulus": 50e6},
         "Plate": {"Poisson ratio": 0.2},
         "Foundation": {"Model": "bilateral"},
         "Discretization": {"Shape": "mesh file", "Mesh file": mesh},
         "Time integration": {"Time step": 2e-4, "End time": 2e-3},
         "Loads": {"Point load 1": {"Magnitude": 5e4,
                                    "Position": f"{middle[0]!r}, "
                                                f"{middle[1]!r}"}},
         "Output": {"Write foundation resultant": "true",
                    "Probe points": f"{middle[0]!r}, {middle[1]!r}; "
                                    f"{corner[0]!r}, {corner[1]!r}"}})


def run(work, name, x0, analysis, gravity):
    mesh = os.path.join(work, name + ".msh")
    write_mesh(mesh, x0, x0)
    folder, result = run_scene(LIFTOFF, work, name,
                               scene(mesh, x0, x0, analysis, gravity))
    if result.returncode != 0:
        check(False, f"{name} runs: {result.stderr.strip()}")
        return None
    with open(os.path.join(folder, "summary.json")) as f:
        status = json.load(f)["status"]
    check(status == "completed", f"{name}: {status}")
    history = read_history(folder)
    # Positions relative to the slab's corner; probes in the order given.
    for column in ("resultant_x [m]", "resultant_y [m]",
                   "max_pressure_x [m]", "max_pressure_y [m]"):
        if column in history:
            history[column] = history[column] - x0
    probes = [c for c in history if c.startswith("w(")]
    return {(f"probe {k}" if c in probes else c):
            history[c] for k, c in enumerate(history)
            if c in probes or "(" not in c}


def compare(work, analysis, gravity):
    at_origin = run(work, f"{analysis}_origin", 0.0, analysis, gravity)
    shifted = run(work, f"{analysis}_shifted", SHIFT, analysis, gravity)
    if at_origin is None or shifted is None:
        return
    worst, worst_column = 0.0, ""
    for column, values in at_origin.items():
        # Round-off itself: relative to the work. The largest pressure's
        # point: equal pressures at mirror Gauss points (the slab settling
        # evenly) are told apart by round-off.
        if column.startswith("max_pressure_"):
            continue
        scale = max(np.max(np.abs(
            at_origin["work [J]" if column.startswith("balance_error")
                      else column])), 1e-300)
        difference = np.max(np.abs(shifted[column] - values)) / scale
        if difference > worst:
            worst, worst_column = difference, column
    check(set(at_origin) == set(shifted) and worst < LIMIT,
          f"{analysis}: {len(at_origin)} columns of the slab at "
          f"({SHIFT:g}, {SHIFT:g}) m against the origin, largest relative "
          f"difference {worst:.1e} ({worst_column}) < {LIMIT:.0e}")
    w = [v for c, v in at_origin.items() if c.startswith("probe")][0]
    print(f"  w at the middle: {w[-1]:.6e} m")


with tempfile.TemporaryDirectory() as work:
    compare(work, "static", 0)
    compare(work, "dynamic", 9.81)
finish()
