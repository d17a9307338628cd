#!/usr/bin/env python3
"""Slabs of different thickness and modulus, each against a scene that
knows no slabs:

- two 4 m SI slabs with a free joint, the loaded one 0.30 m thick and
  1.2 times as stiff (Slabs/Thicknesses, Modulus ratios), the other the
  plate's 0.25 m, on a tensionless bed with self-weight under a pulse:
  the loaded slab moves as a single 0.30 m slab of 36 GPa (its own
  scene), in w, the moments and the stresses at its probes (bending,
  shear, translational and rotary mass, self-weight, moment and stress
  of the thicker section), and each slab settles at rho g H_s / k;
- a half model of three slabs, the outer two alike, against the full
  plate; a half model whose mirror slabs differ is refused.

    slab_sections.py LIFTOFF
"""

import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (read_history, run_scene, run_scene_or_fail,  # noqa: E402
                    scene_text)

LIFTOFF = os.path.abspath(sys.argv[1])

RHO, G, K = 2400, 9.81, 50e6
SI = {
    "Units": {"System": "SI", "Width": 4, "Thickness": 0.25,
              "Young's modulus": 30e9, "Density": RHO,
              "Subgrade modulus": K},
    "Plate": {"Poisson ratio": 0.15},
    "Foundation": {"Model": "tensionless"},
    "Time integration": {"Time step": 2e-4, "End time": 0.004},
}


def quantities(names, points):
    """Output/Probe quantities: each of NAMES at each of POINTS."""
    return ", ".join(f"{n}({x:g}; {y:g})" for n in names for x, y in points)


def same(a, b, what, tolerance=1e-9):
    scale = max(np.max(np.abs(a)), 1e-300)
    error = np.max(np.abs(a - b)) / scale
    check(error < tolerance, f"{what}: relative difference {error:.1e}")


def thicker_slab_is_alone(work, heat=None, tag=""):
    """The 0.30 m slab in the pair against itself alone; with `heat`, a
    Loads/Temperature load 1 on both scenes (runs named with `tag`)."""
    heated = {} if heat is None else {"Loads": {"Temperature load 1": heat}}

    def scene(length, shift, extra):
        load_x = -1.0 + shift
        probes = [(-1.0, 0.5), (-1.9, -1.9), (-0.1, 1), (-0.6, 0.2)]
        moved = [(x + shift, y) for x, y in probes]
        points = "; ".join(f"{x:g}, {y:g}" for x, y in moved)
        return scene_text(SI, {
            "Units": {"Length": length},
            "Discretization": {"Cells along x": 2 * length,
                               "Cells along y": 8},
            "Loads": {"Point load 1": {"Magnitude": 80e3,
                                       "Position": f"{load_x}, 0.5",
                                       "Time history": "sin(1000*t)"}},
            "Output": {"Probe points": points
                       + ("; 2, 0" if "Slabs" in extra else ""),
                       "Probe quantities": quantities(
                           ("M_xx", "M_xy", "Q_x", "sigma_xx"), moved)}},
                heated, extra)
    alone = read_history(run_scene_or_fail(LIFTOFF, work, "alone" + tag, scene(
        4, 0, {"Units": {"Thickness": 0.30, "Young's modulus": 36e9}})))
    pair = read_history(run_scene_or_fail(LIFTOFF, work, "sections" + tag, scene(
        8, -2, {"Slabs": {"Slabs along x": 2, "Thicknesses": "0.30, 0.25",
                          "Modulus ratios": "1.2, 1"}})))
    compared = 0
    for prefix in ("w(", "M_xx(", "M_xy(", "Q_x(", "sigma_xx("):
        mine = [c for c in alone if c.startswith(prefix)]
        theirs = [c for c in pair if c.startswith(prefix)][:len(mine)]
        for a, b in zip(mine, theirs):
            same(alone[a], pair[b], f"0.30 m slab{tag}: {b} against alone {a}")
            compared += 1
    check(compared == 20, f"{compared} probe columns compared (20)")
    if heat is not None:
        return
    other = pair["w(2;0) [m]"]
    weight = RHO * G * 0.25 / K
    check(np.max(np.abs(other - weight)) < 1e-9 * weight,
          f"the 0.25 m slab rests at rho g H / k = {weight:.4e} m "
          f"(largest departure {np.max(np.abs(other - weight)):.1e} m)")
    # Before the pulse acts the loaded slab has settled under its weight.
    w0 = pair["w(-3.9;-1.9) [m]"][0]
    check(abs(w0 - RHO * G * 0.30 / K) < 1e-9 * w0,
          f"the 0.30 m slab settles at rho g H_s / k: {w0:.6e} m")


def symmetric_half(work):
    base = {"Units": {"Length": 6},
            "Slabs": {"Slabs along x": 3, "Thicknesses": "0.2, 0.3, 0.2",
                      "Modulus ratios": "0.8, 1, 0.8",
                      "Shear stiffness": 2e8},
            "Loads": {"Point load 1": {"Magnitude": 60e3,
                                       "Position": "-0.5, 0",
                                       "Time history": "sin(1000*t)"},
                      "Point load 2": {"Magnitude": 60e3,
                                       "Position": "0.5, 0",
                                       "Time history": "sin(1000*t)"}},
            "Output": {"Probe points": "-0.5, 0; -1.5, 1; -2.5, -0.5",
                       "Probe quantities": quantities(
                           ("M_xx", "sigma_xx"), [(-1.5, 1), (-2.5, -0.5)])}}
    full = read_history(run_scene_or_fail(LIFTOFF, work, "full", scene_text(
        SI, base, {"Discretization": {"Cells along x": 12,
                                      "Cells along y": 8}})))
    half = read_history(run_scene_or_fail(LIFTOFF, work, "half", scene_text(
        SI, base, {"Discretization": {"Cells along x": 6,
                                      "Cells along y": 8,
                                      "Symmetry": "half"}})))
    for column in full:
        if column.startswith(("w(", "M_xx(", "sigma_xx(")):
            same(full[column], half[column], f"half against full, {column}",
                 1e-8)
    uneven = merged_slabs(base, {"Thicknesses": "0.2, 0.3, 0.25"})
    _, result = run_scene(LIFTOFF, work, "uneven", scene_text(
        SI, uneven, {"Discretization": {"Cells along x": 6,
                                        "Cells along y": 8,
                                        "Symmetry": "half"}}))
    message = result.stderr.strip().splitlines()[-1:] or [""]
    check(result.returncode != 0 and "slab 3" in message[0]
          and "Symmetry = half" in message[0],
          f"mirror slabs that differ refused: {message[0]}")


def merged_slabs(base, slabs):
    scene = dict(base)
    scene["Slabs"] = {**base["Slabs"], **slabs}
    return scene


with tempfile.TemporaryDirectory() as work:
    thicker_slab_is_alone(work)
    # A permanent curl (the slabs settle curled on their weight) and a
    # pulse of a nonlinear profile: the slab's own alpha dT / H_s, D_s and
    # E_s.
    thicker_slab_is_alone(work, {"Magnitude": 12, "Expansion coefficient": 1e-5,
                                 "Permanent": "true"}, "-curled")
    thicker_slab_is_alone(work, {"Magnitude": 15, "Expansion coefficient": 1e-5,
                                 "Profile": "1, 0.3, 0",
                                 "Time history": "sin(1000*t)"}, "-pulse")
    symmetric_half(work)
finish()
