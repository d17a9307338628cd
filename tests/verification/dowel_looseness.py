#!/usr/bin/env python3
"""Loose dowels against two rigid slabs, solved here by hand.

Two slabs 0.5 x 1 side by side (joint x1 at x = 0) on a bilateral bed
so soft (Gamma = 1e-3) that each moves as a rigid body to about 1e-5, with
three dowels of stiffness C and looseness g on the joint; a uniform
pressure p on one slab only. A rigid slab on Winkler springs has two
unknowns here (the y-symmetry leaves no twist): its centre's w and its
slope along x. With the joint's jump J = w_lower - w_upper, each dowel
passes nothing while |J| <= g and F = C (J - g sign J) beyond; the four
unknowns then solve a 4 x 4 linear system (written below), and whether
the dowels engage follows from the free jump p / k against g.

Checked against that solution: each dowel's force (history.csv) and
the dowels' energy column (N F^2 / 2C), w at both slabs' centres and at
both faces of the joint, for g = 0 (linear
dowels), g below the free jump (engaged with an offset), g above it (all
slack: the unloaded slab does not move), and the load on the other slab
(the forces change sign: the other engaged status). The bed's resultant
equals the load in each (equilibrium).

A dynamic run with loose dowels (a load crossing the joint on a
tensionless bed with self-weight, the dowels' statuses changing as it
goes) stopped at a checkpoint and resumed writes the same history.csv,
byte for byte, as the run without the stop; on two ranks (one slab each)
every column agrees with one rank's to 1e-9 of its largest value.

Positions per joint (Slabs/Dowels/Positions = x1: 0.25; x2: 0.75) on
three slabs under two loads mirrored through the centre: the two dowels,
images of each other under the half-turn, pass equal and opposite forces
(one list for both joints fails this: 0.227 against -0.117).

    dowel_looseness.py LIFTOFF
"""

import filecmp
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (point_load, read_history, run_scene,  # noqa: E402
                    run_scene_or_fail, scene_text)

LIFTOFF = os.path.abspath(sys.argv[1])

GAMMA = 1e-3        # k L^4 / D, L = 1
A, B = 0.5, 1.0     # a slab's length along x and its width
N_DOWELS = 3
C = GAMMA * A * B / N_DOWELS   # the dowels together as stiff as a slab's bed
P = 1.0             # the pressure on the loaded slab
FREE_JUMP = P / GAMMA
PROBES = [(-0.25, 0.0), (0.25, 0.0), (-1e-4, 0.0), (1e-4, 0.0)]


def rigid_slabs(g, loaded):
    """Centre w and slope of both slabs (lower first) and the dowels'
    force, for the pressure on slab `loaded` (0: x < 0, 1: x > 0)."""
    k = GAMMA
    bed = k * A * B * np.diag([1.0, A * A / 12, 1.0, A * A / 12])
    f = np.zeros(4)
    f[2 * loaded] = P * A * B
    # J = (w1 + t1 a/2) - (w2 - t2 a/2).
    e = np.array([1.0, A / 2, -1.0, A / 2])
    x = np.linalg.solve(bed, f)
    jump = e @ x
    if abs(jump) <= g:
        return x, 0.0
    s = np.sign(jump)
    x = np.linalg.solve(bed + N_DOWELS * C * np.outer(e, e),
                        f + N_DOWELS * C * g * s * e)
    jump = e @ x
    check(abs(jump) > g, f"the rigid solution is engaged (|J| = {abs(jump):.4g}"
          f" > g = {g:.4g})")
    return x, C * (jump - g * s)


def w_at(x, point):
    """w of the rigid slabs at a point."""
    lower = point[0] < 0
    w, t, centre = (x[0], x[1], -A / 2) if lower else (x[2], x[3], A / 2)
    return w + t * (point[0] - centre)


def run(work, name, g, loaded):
    intensity = "if(x < 0, 1, 0)" if loaded == 0 else "if(x > 0, 1, 0)"
    text = scene_text(
        {"Analysis": {"Type": "static"},
         "Plate": {"Thickness ratio": 0.05},
         "Foundation": {"Model": "bilateral", "Stiffness": GAMMA},
         "Discretization": {"Cells along x": 8, "Cells along y": 8},
         "Slabs": {"Slabs along x": 2,
                   "Dowels": {"Joints": "x1",
                              "Positions": "0.25, 0.5, 0.75",
                              "Stiffness": C,
                              "Looseness": g}},
         "Loads": {"Pressure 1": {"Region": "whole plate",
                                  "Magnitude": P,
                                  "Intensity": intensity}},
         "Output": {"Probe points": "; ".join(f"{x}, {y}" for x, y in PROBES),
                    "Write foundation resultant": "true"}})
    return read_history(run_scene_or_fail(LIFTOFF, work, name, text))


def compare(work, name, g, loaded):
    h = run(work, name, g, loaded)
    x, force = rigid_slabs(g, loaded)
    scale = FREE_JUMP
    for point in PROBES:
        column = f"w({point[0]:g};{point[1]:g})"
        column = next(c for c in h if c.replace(" ", "") == column)
        error = abs(h[column][-1] - w_at(x, point)) / scale
        check(error < 1e-4, f"{name}: {column} = {h[column][-1]:.6g} against "
              f"the rigid slabs' {w_at(x, point):.6g} (error {error:.1e} of "
              f"p/k)")
    forces = np.array([h[f"dowel_x1_{k}"][-1] for k in (1, 2, 3)])
    scale = max(abs(force), C * FREE_JUMP * 1e-3)
    error = np.max(np.abs(forces - force)) / scale
    check(error < 1e-3, f"{name}: dowel forces {forces} against the rigid "
          f"slabs' {force:.6g} each (error {error:.1e})")
    # The dowels' own energy column: 1/2 C (|J| - g)^2 = F^2 / 2C each.
    energy = N_DOWELS * force ** 2 / (2 * C)
    stored = h["strain"][-1] + h["foundation"][-1] + h["dowels"][-1]
    error = abs(h["dowels"][-1] - energy) / max(energy, 1e-3 * stored)
    check(error < 3e-3, f"{name}: the dowels' energy {h['dowels'][-1]:.6g} "
          f"against the rigid slabs' {energy:.6g} (error {error:.1e})")
    load = P * A * B
    error = abs(h["resultant"][-1] - load) / load
    check(error < 1e-6, f"{name}: the bed's resultant equals the load "
          f"(error {error:.1e})")
    return forces


def dynamic(end_time):
    return scene_text(
        {"Plate": {"Thickness ratio": 0.05},
         "Foundation": {"Model": "tensionless", "Stiffness": 500},
         "Discretization": {"Cells along x": 8, "Cells along y": 4},
         "Slabs": {"Slabs along x": 2,
                   "Dowels": {"Joints": "x1", "Spacing": 0.25,
                              "Stiffness": 200, "Looseness": 2e-4}},
         "Loads": {"Self weight": 5,
                   "Point load 1": {"Magnitude": 300,
                                    "Path": "-0.3 + 6*tau; -0.2"}},
         "Time integration": {"Time step": 0.002, "End time": end_time},
         # Off the joint: a point on it belongs to both slabs.
         "Output": {"Probe points": "-0.1, -0.2; 0.1, -0.2"}})


def resumed_is_uninterrupted(work):
    whole = run_scene_or_fail(LIFTOFF, work, "whole", dynamic(0.1))
    run_scene_or_fail(LIFTOFF, work, "resumed", dynamic(0.05))
    folder, result = run_scene(LIFTOFF, work, "resumed", dynamic(0.1),
                               ["--resume"])
    check(result.returncode == 0, f"the resume runs ({result.stderr.strip()})")
    h = read_history(whole)
    forces = np.array([h[c] for c in h if c.startswith("dowel_")])
    check(np.any(forces == 0) and np.any(forces != 0),
          "the dynamic run has slack and engaged dowels")
    check(filecmp.cmp(os.path.join(whole, "history.csv"),
                      os.path.join(folder, "history.csv"), shallow=False),
          "resumed at tau = 0.05: history.csv byte for byte the whole run's")
    two, result = run_scene(LIFTOFF, work, "two_ranks", dynamic(0.1),
                            ranks=2)
    check(result.returncode == 0, f"two ranks run ({result.stderr.strip()})")
    other = read_history(two)
    worst = max(np.max(np.abs(h[c] - other[c])) / max(np.max(np.abs(h[c])),
                                                       1e-300)
                for c in h if c not in ("balance_error",))
    check(worst < 1e-9, f"two ranks: every column within {worst:.1e} of one "
          "rank's")


def positions_per_joint(work):
    """Three slabs (joints x1 at x = -1/6, x2 at 1/6), one dowel on each
    at its own position (x1: 0.25, x2: 0.75 from the bottom edge), under
    two loads mirrored through the centre: the half-turn about the centre
    takes one dowel onto the other and the lower slab of x1 onto the upper
    of x2, so their forces are equal and opposite; the same list for both
    joints (each at 0.25) would put the second dowel where the loads
    differ."""
    text = scene_text(
        {"Analysis": {"Type": "static"},
         "Foundation": {"Model": "bilateral", "Stiffness": 100},
         "Discretization": {"Cells along x": 12, "Cells along y": 8},
         "Slabs": {"Slabs along x": 3,
                   "Dowels": {"Joints": "x1, x2",
                              "Positions": "x1: 0.25; x2: 0.75",
                              "Stiffness": 50}}},
        point_load(1, -0.3, -0.2, 1), point_load(2, 0.3, 0.2, 1))
    h = read_history(run_scene_or_fail(LIFTOFF, work, "per_joint", text))
    a, b = h["dowel_x1_1"][-1], h["dowel_x2_1"][-1]
    check(abs(a) > 1e-3 and abs(a + b) < 1e-9 * abs(a),
          f"positions per joint: the dowels at x1: 0.25 and x2: 0.75 pass "
          f"{a:.10f} and {b:.10f}, equal and opposite")


def main():
    with tempfile.TemporaryDirectory() as work:
        compare(work, "linear", 0.0, 0)
        engaged = compare(work, "engaged", 0.4 * FREE_JUMP, 0)
        check(np.all(engaged > 0), "engaged: the lower slab's w ahead, "
              "forces > 0")
        slack = compare(work, "slack", 1.5 * FREE_JUMP, 0)
        check(np.all(slack == 0), "slack: no dowel passes a force")
        other = compare(work, "other side", 0.4 * FREE_JUMP, 1)
        check(np.allclose(other, -engaged, rtol=1e-6, atol=0),
              "the load on the other slab: the same forces, negative")
        positions_per_joint(work)
        resumed_is_uninterrupted(work)
    finish()


main()
