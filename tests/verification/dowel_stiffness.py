#!/usr/bin/env python3
"""A dowel's stiffness and bearing stress, and dowels as a joint's springs.

1. Friberg's bar, solved here by beam finite elements: a steel bar of
   diameter d on Winkler springs K d in the concrete of each slab
   (Euler-Bernoulli, Hermite cubics with the consistent spring matrix,
   600 elements over 12 / beta on each side: the end's influence decays
   as exp(-12)), and bare across the joint's opening z (the exact
   Timoshenko element: bending and shear, shear area 0.9 A).
   The right slab is moved by Delta = 1 against the left one; the shear
   the bar carries across the opening is the stiffness C, and K times the
   bar's deflection at the face of the concrete per unit force is the
   bearing stress per unit force. liftoff's summary gives C from its
   closed form (doc/model.md) for three bars and openings, and the
   largest bearing stress of a loaded dowel: both within 1e-5 (the
   summary's six digits; measured 4e-8 to 2.3e-6).
2. Dowels at spacing s of stiffness C and the smeared springs
   AGG = C / s give the same joint as s -> 0: two 6 m x 3 m slabs, a disc
   load tangent to the joint, f = AGG / (k l) = 10; the difference of the
   LTE shrinks with s (0.25 m, 0.125 m, 0.0625 m) at about s^2 (measured
   0.821, 0.144, 0.029 points), and at s = 0.0625 m is below 0.2 points.

    dowel_stiffness.py LIFTOFF
"""

import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..",
                                "scripts"))
from checks import check, finish  # noqa: E402
from lte_fits import radius_of_relative_stiffness  # noqa: E402
from scenes import (read_history, run_scene, run_scene_or_fail,  # noqa: E402
                    scene_text)

LIFTOFF = os.path.abspath(sys.argv[1])

E, H, NU, K, A, P = 30e9, 0.25, 0.15, 50e6, 0.15, 40e3
ELL = radius_of_relative_stiffness(E, H, NU, K)
STEEL, STEEL_NU = 200e9, 0.3


def beam_elements(ei, length, shear_parameter=0.0, foundation=0.0):
    """A beam element's stiffness (Hermite cubics; with shear_parameter
    phi = 12 EI / (G A_s L^2) the exact Timoshenko element) plus the
    consistent matrix of springs `foundation` per unit length, and the
    springs' load for a unit displacement of their support."""
    phi, L = shear_parameter, length
    bending = ei / ((1 + phi) * L**3) * np.array(
        [[12, 6 * L, -12, 6 * L],
         [6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L],
         [-12, -6 * L, 12, -6 * L],
         [6 * L, (2 - phi) * L * L, -6 * L, (4 + phi) * L * L]])
    springs = foundation * L / 420 * np.array(
        [[156, 22 * L, 54, -13 * L],
         [22 * L, 4 * L * L, 13 * L, -3 * L * L],
         [54, 13 * L, 156, -22 * L],
         [-13 * L, -3 * L * L, -22 * L, 4 * L * L]])
    load = foundation * L * np.array([0.5, L / 12, 0.5, -L / 12])
    return bending + springs, load


def friberg_beam(d, support, z):
    """C and the bearing stress per unit force of a bar, by beam finite
    elements: the right slab moved by Delta = 1 against the left one."""
    ei = STEEL * math.pi * d**4 / 64
    ga = STEEL / (2 * (1 + STEEL_NU)) * 0.9 * math.pi * d * d / 4
    kb = support * d
    beta = (kb / (4 * ei)) ** 0.25
    n = 600                      # elements on each side, beta h = 0.02
    h = 12 / beta / n
    # Elements: n in the left concrete, the opening (if any), n in the right.
    elements = [("left", h)] * n + ([("gap", z)] if z > 0 else []) \
        + [("right", h)] * n
    size = 2 * (len(elements) + 1)
    matrix, rhs = np.zeros((size, size)), np.zeros(size)
    for e, (where, length) in enumerate(elements):
        if where == "gap":
            local, load = beam_elements(ei, length, 12 * ei / (ga * length**2))
        else:
            local, load = beam_elements(ei, length, foundation=kb)
        dofs = slice(2 * e, 2 * e + 4)
        matrix[dofs, dofs] += local
        if where == "right":
            rhs[dofs] += load
    u = np.linalg.solve(matrix, rhs)
    face = 2 * (n + (1 if z > 0 else 0))   # the right slab's face
    # The shear across the opening: all the springs of the left slab
    # carry, kb int y ds (the translational entries of their forces).
    left = np.zeros(size)
    for e in range(n):
        local, _ = beam_elements(0.0, h, foundation=kb)
        left[2 * e:2 * e + 4] += local @ u[2 * e:2 * e + 4]
    shear = abs(left[0::2].sum())
    return shear, support * abs(u[face] - 1.0) / shear


def summary_values(folder):
    values = {}
    with open(os.path.join(folder, "summary.txt")) as f:
        for line in f:
            if ":" in line:
                key, _, value = line.rpartition(":")
                try:
                    values[key.strip()] = float(value)
                except ValueError:
                    pass
    return values


def si_units():
    return {"Units": {"System": "SI", "Length": 6, "Width": 6, "Thickness": H,
                      "Young's modulus": E, "Density": 2400, "Gravity": 0,
                      "Subgrade modulus": K},
            "Plate": {"Poisson ratio": NU},
            "Analysis": {"Type": "static"},
            "Foundation": {"Model": "bilateral"}}


def disc_load():
    return {"Loads": {"Patch load 1": {"Magnitude": P / (math.pi * A * A),
                                       "Path": f"0; {-A}", "Shape": "disc",
                                       "Size": 2 * A}},
            "Output": {"Probe points": "0, -1e-7; 0, 1e-7"}}


def bar_against_bvp(work, d, support, z, fields=False):
    text = scene_text(si_units(), disc_load(), {
        "Output": {"VTU interval": 1 if fields else 0},
        "Discretization": {"Cells along x": 12, "Cells along y": 12},
        "Slabs": {"Slabs along y": 2,
                  "Dowels": {"Joints": "y1", "Positions": 3.0,
                             "Diameter": d, "Steel modulus": STEEL,
                             "Steel Poisson ratio": STEEL_NU,
                             "Modulus of dowel support": support,
                             "Joint opening": z}}})
    folder = run_scene_or_fail(LIFTOFF, work, f"bar_{d}_{z}", text)
    summary = summary_values(folder)
    stiffness, bearing = friberg_beam(d, support, z)
    got = summary["stiffness C [N/m]"]
    error = abs(got - stiffness) / stiffness
    check(error < 1e-5, f"d = {d} m, K = {support:g}, z = {z} m: C = {got:.6g}"
          f" N/m against the beam's {stiffness:.6g} (error {error:.1e})")
    force = next(v for k, v in summary.items()
                 if k.startswith("largest force, dowel_y1_1"))
    stress = summary["largest bearing stress [Pa]"]
    error = abs(stress - bearing * force) / (bearing * force)
    check(error < 1e-5, f"  bearing stress {stress:.6g} Pa under {force:.4g} N"
          f" against the beam's {bearing * force:.6g} (error {error:.1e})")
    if fields:
        dowel_field_file(folder, bearing)
        two = run_scene(LIFTOFF, work, f"bar_{d}_{z}_np2", text, ranks=2)[0]
        dowel_field_file(two, bearing)


def dowel_field_file(folder, bearing):
    """The dowels' field file of a static run: the dowel at (0, 0) m with
    history.csv's force and the beam's bearing stress under it."""
    import meshio
    with open(os.path.join(folder, "dowels.pvd")) as f:
        record = f.read()
    piece = os.path.join(folder, "dowels_00000.vtu")
    check('file="dowels_00000.vtu"' in record and os.path.exists(piece),
          f"{os.path.basename(folder)}: dowels.pvd names dowels_00000.vtu")
    # One file on any number of ranks (an empty piece stops ParaView).
    pieces = [n for n in os.listdir(folder) if n.startswith("dowels_")]
    check(pieces == ["dowels_00000.vtu"], f"  the dowels' files: {pieces}")
    points = meshio.read(piece)
    force = read_history(folder)["dowel_y1_1 [N]"][-1]
    got = points.point_data["force"][0]
    stress = points.point_data["bearing_stress"][0]
    check(len(points.points) == 1 and np.allclose(points.points[0], 0)
          and abs(got - force) <= 1e-6 * abs(force)
          and abs(stress - bearing * abs(force)) <= 1e-5 * bearing * abs(force),
          f"  its field file: one dowel at (0, 0) m, force {got:.6g} N "
          f"(history {force:.6g}), bearing stress {stress:.6g} Pa (beam "
          f"{bearing * abs(force):.6g})")


def lte(work, name, slabs):
    text = scene_text(si_units(), disc_load(), {
        "Discretization": {"Cells along x": 48, "Cells along y": 24},
        "Slabs": dict({"Slabs along y": 2}, **slabs)})
    history = read_history(run_scene_or_fail(LIFTOFF, work, name, text))
    return 100 * history["w(0;1e-07) [m]"][0] / history["w(0;-1e-07) [m]"][0]


def dowels_as_springs(work):
    agg = 10 * K * ELL
    smeared = lte(work, "smeared", {"Shear stiffness": agg})
    print(f"AGG = {agg:.4g} N/m^2: LTE {smeared:.3f}")
    differences = []
    for spacing in [0.25, 0.125, 0.0625]:
        doweled = lte(work, f"dowels_{spacing}", {
            "Dowels": {"Joints": "y1", "Spacing": spacing,
                       "Stiffness": agg * spacing}})
        differences.append(abs(doweled - smeared))
        print(f"s = {spacing} m, C = {agg * spacing:.4g} N/m: LTE "
              f"{doweled:.3f}, {differences[-1]:.3f} points from the springs")
    for coarse, fine in zip(differences, differences[1:]):
        check(fine < coarse / 3, f"halving s: the difference {coarse:.3f} ->"
              f" {fine:.3f} points (at least 3 times smaller)")
    check(differences[-1] < 0.2, f"s = 0.0625 m: {differences[-1]:.3f} points"
          " from the smeared springs")


with tempfile.TemporaryDirectory() as work:
    for d, support, z in [(0.032, 407e9, 0.006), (0.025, 300e9, 0.0),
                          (0.038, 800e9, 0.025)]:
        bar_against_bvp(work, d, support, z, fields=d == 0.032)
    dowels_as_springs(work)
finish()
