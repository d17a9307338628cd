#!/usr/bin/env python3
"""The two limits of a joint, each against a scene without one:

- a tied joint is no joint: two slabs tied along x = 0 and the one slab
  they make, with the same cells, on a tensionless bed with self-weight
  under a dynamic point load, give every column of history.csv alike to
  round-off (relative 1e-9 of each column's largest value);
- a free joint passes nothing: of two 4 m slabs side by side with
  Shear stiffness 0, the loaded one moves as that slab alone (its own
  scene, the load and the probes moved with it), to round-off, and the
  other one rests on its bed under its weight.

    joint_limits.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

DYNAMIC = {
    "Plate": {"Thickness ratio": 0.05},
    "Foundation": {"Model": "tensionless", "Stiffness": 500},
    "Loads": {"Self weight": 5},
    "Time integration": {"Time step": 0.002, "End time": 0.04},
}


def same(a, b, what):
    scale = max(np.max(np.abs(a)), 1e-300)
    error = np.max(np.abs(a - b)) / scale
    check(error < 1e-9, f"{what}: relative difference {error:.1e}")


def tied_is_monolithic(work):
    load = {"Loads": {"Point load 1": {"Magnitude": 200,
                                       "Position": "-0.1, 0.05"}},
            "Output": {"Probe points": "-0.1, 0.05; 0, 0; 0.3, -0.2",
                       "Write foundation resultant": "true"}}
    mesh = {"Discretization": {"Cells along x": 8, "Cells along y": 8}}
    one = read_history(run_scene_or_fail(
        LIFTOFF, work, "monolithic", scene_text(DYNAMIC, mesh, load)))
    two = read_history(run_scene_or_fail(
        LIFTOFF, work, "tied", scene_text(
            DYNAMIC, mesh, load,
            {"Slabs": {"Slabs along x": 2, "Tied joints": "x1"}})))
    # The tied joint's springs are a term of the system (its energy
    # column) that holds nothing.
    check(np.all(two.pop("joint_springs") == 0),
          "tied: the joint's springs store nothing")
    check(list(one) == list(two), "tied: the same columns")
    # The joint's nodes are there twice, one copy constrained to the other.
    duplicated = 3 * (2 * 8 + 1)
    check(np.all(two["dofs"] == one["dofs"] + duplicated),
          f"tied: {duplicated} dofs more, the joint's nodes twice")
    for name in one:
        if name not in ("dofs", "balance_error"):
            same(one[name], two[name], f"tied against monolithic, {name}")
    # The balance is a difference of energies: its round-off is theirs.
    same(one["balance_error"] + one["work"], two["balance_error"] + one["work"],
         "tied against monolithic, balance_error (against the work)")


SI = {
    "Units": {"System": "SI", "Width": 4, "Thickness": 0.25,
              "Young's modulus": 30e9, "Density": 2400,
              "Subgrade modulus": 50e6},
    "Plate": {"Poisson ratio": 0.15},
    "Foundation": {"Model": "tensionless"},
    "Time integration": {"Time step": 2e-4, "End time": 0.004},
}


def free_is_alone(work):
    def scene(length, shift, extra):
        load_x, probes = -1.0 + shift, [(-1.0, 0.5), (-1.9, -1.9), (-0.1, 1)]
        return scene_text(SI, {
            "Units": {"Length": length},
            "Discretization": {"Cells along x": 2 * length,
                               "Cells along y": 8},
            "Loads": {"Point load 1": {"Magnitude": 50e3,
                                       "Position": f"{load_x}, 0.5",
                                       "Time history": "sin(1000*t)"}},
            "Output": {"Probe points": "; ".join(
                f"{x + shift:g}, {y:g}" for x, y in probes)
                + ("; 2, 0" if extra else "")}}, extra)
    alone = read_history(run_scene_or_fail(
        LIFTOFF, work, "alone", scene(4, 0, {})))
    pair = read_history(run_scene_or_fail(
        LIFTOFF, work, "free", scene(8, -2, {"Slabs": {"Slabs along x": 2}})))
    for k, column in enumerate(c for c in alone if c.startswith("w(")):
        paired = [c for c in pair if c.startswith("w(")][k]
        same(alone[column], pair[paired], f"free: {paired} against {column}")
    other = pair["w(2;0) [m]"]
    weight = 2400 * 9.81 * 0.25 / 50e6
    check(np.max(np.abs(other - weight)) < 1e-9 * weight,
          f"free: the unloaded slab rests at rho g H / k = {weight:.4e} m "
          f"(largest departure {np.max(np.abs(other - weight)):.1e} m)")


with tempfile.TemporaryDirectory() as work:
    tied_is_monolithic(work)
    free_is_alone(work)
finish()
