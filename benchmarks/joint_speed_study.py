#!/usr/bin/env python3
"""The truck of prm/doweled-joint-truck.prm crossing the joint at several
speeds, on a tensionless and on a bilateral bed, with loose dowels (g =
0.05 mm), tight ones (g = 0) and the same dowels smeared into aggregate
interlock AGG = C / s (doc/studies.md, "A truck crossing a doweled joint").

    /usr/bin/python3 benchmarks/joint_speed_study.py build/liftoff [DT]
        [--speeds 5,20,40] [--beds tensionless,bilateral]
        [--time-step-divisor K] [--mesh-factor M]

With DT (K, top minus bottom; -15 for a night) the slabs are curled by a
permanent temperature difference (alpha = 1e-5 / K) before the truck comes,
and only the dowelled joints are run. The scene's 1 ms step is divided by
K and its 36 x 15 cells multiplied by M along each side, for the figures'
discretisation error.

prints one row per run: the LTE as the rear axle's outer wheel reaches the
joint (w at both faces in its path, from the settled state, w_unloaded /
w_loaded), the largest dowel force, the largest principal moment as a
stress 6 M / h^2 and the smallest contact fraction.
"""

import argparse
import os
import re
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "common"))
from scenes import read_history, run_scene_or_fail  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("liftoff")
parser.add_argument("curl", nargs="?", type=float, default=0.0)
parser.add_argument("--speeds", default="5,20,40")
parser.add_argument("--beds", default="tensionless,bilateral")
parser.add_argument("--time-step-divisor", type=int, default=1)
parser.add_argument("--mesh-factor", type=int, default=1)
ARGS = parser.parse_args()
LIFTOFF = os.path.abspath(ARGS.liftoff)
CURL = ARGS.curl
SCENE = os.path.join(os.path.dirname(__file__), "..", "prm",
                     "doweled-joint-truck.prm")
H = 0.25
C = 1.17605e8          # the scene's dowels (its summary)
SPACING = 0.3


def variant(text, speed, bed, joint):
    text = text.replace("-3 + 20*t", f"-3 + {speed}*t")
    # The rear axle (4 m behind) reaches the joint at t = 7 / v.
    text = re.sub(r"set End time  = \S+", f"set End time  = {8.0 / speed:g}",
                  text)
    text = text.replace("set Model = tensionless", f"set Model = {bed}")
    text = text.replace("set Time step = 1e-3",
                        f"set Time step = {1e-3 / ARGS.time_step_divisor!r}")
    text = text.replace("set Cells along x     = 36",
                        f"set Cells along x     = {36 * ARGS.mesh_factor}")
    text = text.replace("set Cells along y     = 15",
                        f"set Cells along y     = {15 * ARGS.mesh_factor}")
    text = text.replace("  set VTU interval = 25",
                        "  set VTU interval = 0\n"
                        "  set Write moment extremes = true")
    if CURL != 0:
        text = text.replace("subsection Loads\n", "subsection Loads\n"
                            "  subsection Temperature load 1\n"
                            f"    set Magnitude             = {CURL:g}\n"
                            "    set Expansion coefficient = 1e-5\n"
                            "    set Permanent             = true\n"
                            "  end\n")
    if joint == "tight":
        text = text.replace("set Looseness                = 5e-5",
                            "set Looseness                = 0")
    if joint == "interlock":
        text = re.sub(r"  subsection Dowels.*?\n  end\n",
                      f"  set Shear stiffness = {C / SPACING:g}\n", text,
                      flags=re.S)
    return text


def measure(history):
    lower, upper = history["w(-0.0001;-1.7) [m]"], history["w(0.0001;-1.7) [m]"]
    rear = history["vehicle_1_x [m]"] - 4
    # The rear outer wheel (radius 0.15 m) tangent to the joint.
    at = np.argmin(np.abs(rear + 0.15))
    lte = (upper[at] - upper[0]) / (lower[at] - lower[0])
    dowels = [history[c] for c in history if c.startswith("dowel_")]
    force = max(np.max(np.abs(d)) for d in dowels) if dowels else np.nan
    stress = 6 * np.max(history["max_M_1 [N m/m]"]) / H**2
    return lte, force, stress, np.min(history["contact_fraction"])


with open(SCENE) as f:
    base = f.read()
print("speed  bed          joint       LTE    max dowel [kN]  "
      "max stress [MPa]  min contact")
with tempfile.TemporaryDirectory() as work:
    for speed in [int(v) for v in ARGS.speeds.split(",")]:
        for bed in ARGS.beds.split(","):
            for joint in (["loose", "tight"] if CURL else
                          ["loose", "tight", "interlock"]):
                name = f"v{speed}_{bed}_{joint}"
                text = variant(base, speed, bed, joint)
                text = text.replace("output-doweled-joint-truck", name)
                history = read_history(run_scene_or_fail(LIFTOFF, work, name,
                                                         text))
                lte, force, stress, contact = measure(history)
                print(f"{speed:5d}  {bed:11s}  {joint:10s} {lte:6.3f}  "
                      f"{force / 1e3:14.2f}  {stress / 1e6:16.3f}  "
                      f"{contact:11.3f}", flush=True)
