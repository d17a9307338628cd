#!/usr/bin/env python3
"""Discs and annuli as their meshes carry them: the area the mapped cells
cover, a free Q1 disc's equilibrium, and points on the rim (issue 46,
findings 4, 7 and 8).

Area. The coarse mesh's boundary is n arcs of the circle, each mapped by
the element's degree through its nodes on the circle: degree 1 makes
chords (the area of the n-gon, n/2 R^2 sin(2 pi/n)), degree 2 arcs of
parabolas through the arc's ends and middle, whose area beyond the chord
is 4/3 of the triangle of the three points (Archimedes): 2/3 chord x
sagitta. A uniform pressure on a bilateral bed with Write foundation
resultant gives `contact_area` (the mesh's area) and `resultant` (the
pressure's); against those closed forms (Q2 annulus of 8 arcs, Q2 disc of
8 arcs, Q1 disc), and against the circles' area within
1e-3 (TimeStepper::setup()), or a warning that names the
measured error.

Equilibrium. A free disc on a bilateral bed under a unit load at
(0.2, 0.1): the bed's resultant is 1 at (0.2, 0.1) to round-off with Q1
elements as with Q2 (a Q1 element on cells mapped by degree 2 resisted
the rigid tilt: the centre was 0.0061 off).

Rim. A point on the circle lies outside the mapped cells between their
nodes; the load, a probe, a profile's end, a point load moving onto the
rim and its riding probe are taken at the mesh's nearest point: the run
completes, the bed's resultant centre lies within the mapping's gap of
the point (below 1e-4 on 16 arcs of degree 2: 4.6e-5 R), and w on the
rim is within 1 % of w 1e-3 R inside it.

    curved_meshes.py LIFTOFF
"""

import json
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (point_load, pressure, read_history,  # noqa: E402
                    read_profile, run_scene, scene_text)

LIFTOFF = sys.argv[1]
R = 0.5


def enclosed_area(radius, n_arcs, degree):
    """The area inside n_arcs equal arcs of the circle mapped by `degree`."""
    theta = 2 * np.pi / n_arcs
    polygon = n_arcs * 0.5 * radius**2 * np.sin(theta)
    if degree == 1:
        return polygon
    chord = 2 * radius * np.sin(theta / 2)
    sagitta = radius * (1 - np.cos(theta / 2))
    return polygon + n_arcs * 2.0 / 3.0 * chord * sagitta


def run(work, name, *parts):
    """Run a static scene on a bilateral bed (the shape and loads in
    PARTS); its history's last row and its summary."""
    text = scene_text({"Analysis": {"Type": "static"},
                       "Foundation": {"Model": "bilateral", "Stiffness": 300},
                       "Output": {"Write foundation resultant": "true",
                                  "Write energies": "false"}}, *parts)
    folder, result = run_scene(LIFTOFF, work, name, text)
    if result.returncode != 0:
        check(False, f"{name} runs: {result.stderr.strip()}")
        return None, None
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    history = read_history(folder)
    return {k: v[-1] for k, v in history.items()}, summary


def shape(name, degree, refinements=0, **extra):
    return {"Discretization": {"Shape": name, "Radius": R,
                               "Polynomial degree": degree,
                               "Global refinements": refinements, **extra}}


def check_area(work, name, scene_shape, *extra, exact, mesh_area):
    """A unit pressure on SCENE_SHAPE (and EXTRA parts): the mesh's area
    against the closed form MESH_AREA; within 1e-3 of the shape's EXACT
    area, or warned of."""
    row, summary = run(work, name, scene_shape, pressure(1), *extra)
    if row is None:
        return
    area = row["contact_area"]
    check(abs(area / mesh_area - 1) < 1e-10,
          f"{name}: mesh area {area:.10f} against {mesh_area:.10f} of its "
          f"arcs (relative {abs(area / mesh_area - 1):.1e} < 1e-10)")
    check(abs(row["resultant"] / area - 1) < 1e-10,
          f"{name}: the pressure's resultant {row['resultant']:.10f} is "
          f"the mesh's area")
    error = abs(area / exact - 1)
    warned = summary["status"] == "completed with warnings" and \
        "area" in summary.get("warning", "")
    if error <= 1e-3:
        check(summary["status"] == "completed",
              f"{name}: area within {error:.1e} <= 1e-3 of the shape's, "
              f"status {summary['status']}")
    else:
        figure = float(summary.get("warning", "by 0 ").split(" by ")[1]
                       .split(" ")[0]) if warned else 0
        check(warned and abs(figure / error - 1) < 1e-6,
              f"{name}: area {error:.4f} off the shape's: warned with "
              f"{figure:.6f} ({summary['status']})")


def check_areas(work):
    annulus = np.pi * (R**2 - 0.05**2)
    check_area(work, "annulus_q2", shape("annulus", 2, **{"Inner radius":
                                                           0.05}),
               {"Output": {"Probe points": "0.3, 0"}},
               exact=annulus,
               mesh_area=enclosed_area(R, 8, 2) - enclosed_area(0.05, 8, 2))
    check_area(work, "disc_q2", shape("disc", 2), exact=np.pi * R**2,
               mesh_area=enclosed_area(R, 8, 2))
    check_area(work, "disc_q1", shape("disc", 1), exact=np.pi * R**2,
               mesh_area=enclosed_area(R, 8, 1))


def check_q1_equilibrium(work):
    for degree in (1, 2):
        name = f"equilibrium_q{degree}"
        row, summary = run(work, name, shape("disc", degree, 2),
                           point_load(1, 0.2, 0.1, 1))
        if row is None:
            continue
        imbalance = summary["static equilibrium, bed against loads "
                            "(relative)"]
        offset = np.hypot(row["resultant_x"] - 0.2, row["resultant_y"] - 0.1)
        check(imbalance < 1e-10 and abs(row["resultant"] - 1) < 1e-10
              and offset < 1e-10,
              f"{name}: resultant {row['resultant']:.12f} at "
              f"({row['resultant_x']:.12f}, {row['resultant_y']:.12f}), "
              f"{offset:.1e} off (0.2, 0.1), imbalance {imbalance:.1e}")


def check_rim(work):
    rim = (0.3, 0.4)
    inside = (0.3 * 0.999, 0.4 * 0.999)
    row, summary = run(
        work, "rim_static", shape("disc", 2, 1), point_load(1, *rim, 1),
        {"Output": {"Probe points": f"{rim[0]}, {rim[1]}; "
                                    f"{inside[0]}, {inside[1]}",
                    "Profile start": "0, 0",
                    "Profile end": f"{rim[0]}, {rim[1]}",
                    "Profile points": 11}})
    if row is not None:
        offset = np.hypot(row["resultant_x"] - rim[0],
                          row["resultant_y"] - rim[1])
        check(summary["status"] == "completed" and offset < 1e-4,
              f"rim_static: {summary['status']}, the bed's centre "
              f"{offset:.1e} off the load on the rim (< 1e-4)")
        w_rim = row[f"w({rim[0]};{rim[1]})"]
        w_in = row[f"w({inside[0]:g};{inside[1]:g})"]
        check(abs(w_rim / w_in - 1) < 1e-2,
              f"rim_static: w on the rim {w_rim:.6g} against {w_in:.6g} "
              f"1e-3 R inside")
        s, w = read_profile(os.path.join(work, "rim_static"))
        check(abs(w[-1] - w_rim) < 1e-12 * abs(w_rim),
              f"rim_static: the profile ends at the rim probe's w "
              f"({w[-1]:.10g})")
    text = scene_text(
        {"Foundation": {"Model": "bilateral", "Stiffness": 300},
         "Time integration": {"Time step": 1e-3, "End time": 0.01},
         "Output": {"Riding probes": "w@point_load_1"}},
        shape("disc", 2, 1),
        {"Loads": {"Point load 1": {"Magnitude": 1, "Path":
                                    "0.3*(0.9+10*tau); 0.4*(0.9+10*tau)"}}})
    folder, result = run_scene(LIFTOFF, work, "rim_moving", text)
    rows = len(read_history(folder)["tau"]) if result.returncode == 0 else 0
    check(result.returncode == 0 and rows == 11,
          f"rim_moving: a point load moving onto the rim runs to r = R "
          f"({rows} rows; {result.stderr.strip()[:200]})")


with tempfile.TemporaryDirectory() as work:
    check_areas(work)
    check_q1_equilibrium(work)
    check_rim(work)
finish()
