#!/usr/bin/env python3
"""The profile along a joint (Output/Joint profiles, joints.csv) against
two rigid slabs solved here by hand, and a resumed and a two-rank run
against the uninterrupted one-rank run.

Two slabs 0.5 x 1 side by side (joint x1 at x = 0) on a bilateral bed so
soft (Gamma = 1e-3) that each moves as a rigid body to about 1e-5, joined
by aggregate interlock AGG, a uniform pressure p on the left slab. Each
rigid slab has its centre's w and its slope along x (the y-symmetry
leaves no twist); the joint's springs add AGG B (J e e^T) with the jump
J = w_lower - w_upper at the faces, a 4 x 4 system. Checked along the
joint: w on both faces at every point, the shear per length AGG J, the
load transfer w_upper / w_lower, the points (the joint's Gauss points:
3 per face of the 8 Q2 faces, s in (0, 1), x = 0), and the history's
shear_x1 = AGG J B (the profile's forces add up to the joint's).

    joint_profile.py LIFTOFF
"""

import csv
import filecmp
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import (read_history, run_scene, run_scene_or_fail,  # noqa: E402
                    scene_text)

LIFTOFF = os.path.abspath(sys.argv[1])

GAMMA = 1e-3        # k L^4 / D, L = 1
A, B = 0.5, 1.0     # a slab's length along x and its width
AGG = GAMMA * A     # the joint as stiff as a slab's bed
P = 1.0


def rigid_faces():
    """w of the lower and the upper slab at the joint."""
    bed = GAMMA * A * B * np.diag([1.0, A * A / 12, 1.0, A * A / 12])
    e = np.array([1.0, A / 2, -1.0, A / 2])
    f = np.array([P * A * B, 0.0, 0.0, 0.0])
    x = np.linalg.solve(bed + AGG * B * np.outer(e, e), f)
    return x[0] + x[1] * A / 2, x[2] - x[3] * A / 2


def read_profile(folder):
    with open(os.path.join(folder, "joints.csv")) as f:
        return list(csv.DictReader(f))


def static_profile(work):
    text = scene_text(
        {"Analysis": {"Type": "static"},
         "Foundation": {"Model": "bilateral", "Stiffness": GAMMA},
         "Discretization": {"Cells along x": 8, "Cells along y": 8},
         "Slabs": {"Slabs along x": 2, "Shear stiffness": AGG},
         "Loads": {"Pressure 1": {"Magnitude": P,
                                  "Intensity": "if(x < 0, 1, 0)"}},
         "Output": {"Joint profiles": "true"}})
    folder = run_scene_or_fail(LIFTOFF, work, "static", text)
    rows = read_profile(folder)
    lower, upper = rigid_faces()
    scale = P / GAMMA
    check(len(rows) == 24, f"{len(rows)} points along the joint (24)")
    s = np.array([float(r["s"]) for r in rows])
    check(np.all(np.diff(s) > 0) and s[0] > 0 and s[-1] < 1
          and all(r["joint"] == "x1" and float(r["x"]) == 0 for r in rows),
          "the points: joint x1, x = 0, s rising within (0, 1)")
    for name, exact in (("w_lower", lower), ("w_upper", upper)):
        values = np.array([float(r[name]) for r in rows])
        error = np.max(np.abs(values - exact)) / scale
        check(error < 1e-4, f"{name} = {values.mean():.6g} against the rigid "
              f"slabs' {exact:.6g} (error {error:.1e} of p/k)")
    shear = np.array([float(r["shear"]) for r in rows])
    exact = AGG * (lower - upper)
    error = np.max(np.abs(shear - exact)) / abs(exact)
    check(error < 1e-3, f"shear per length {shear.mean():.6g} against AGG J "
          f"= {exact:.6g} (error {error:.1e})")
    lte = np.array([float(r["lte"]) for r in rows])
    check(np.max(np.abs(lte - upper / lower)) < 1e-3,
          f"load transfer {lte.mean():.6f} against {upper / lower:.6f}")
    total = read_history(folder)["shear_x1"][-1]
    error = abs(total - exact * B) / abs(exact * B)
    check(error < 1e-3, f"history's shear_x1 = {total:.6g} against AGG J B "
          f"(error {error:.1e})")


def dynamic(end_time):
    return scene_text(
        {"Foundation": {"Model": "tensionless", "Stiffness": 500},
         "Discretization": {"Cells along x": 8, "Cells along y": 4},
         "Slabs": {"Slabs along x": 2, "Shear stiffness": 300},
         "Loads": {"Self weight": 5,
                   "Point load 1": {"Magnitude": 300,
                                    "Path": "-0.3 + 6*tau; -0.2"}},
         "Time integration": {"Time step": 0.002, "End time": end_time},
         "Output": {"Joint profiles": "true",
                    "Profile times": "0.02, 0.05, 0.08",
                    "Probe points": "-0.1, -0.2; 0.1, -0.2"}})


def resumed_and_two_ranks(work):
    whole = run_scene_or_fail(LIFTOFF, work, "whole", dynamic(0.1))
    run_scene_or_fail(LIFTOFF, work, "resumed", dynamic(0.06))
    folder, result = run_scene(LIFTOFF, work, "resumed", dynamic(0.1),
                               ["--resume"])
    check(result.returncode == 0, f"the resume runs ({result.stderr.strip()})")
    rows = read_profile(whole)
    check(len(rows) == 3 * 12, f"{len(rows)} rows: 3 times x 12 points")
    check(filecmp.cmp(os.path.join(whole, "joints.csv"),
                      os.path.join(folder, "joints.csv"), shallow=False),
          "resumed at tau = 0.06: joints.csv byte for byte the whole run's")
    two = os.path.join(work, "two_ranks")
    with open(two + ".prm", "w") as f:
        f.write(dynamic(0.1) + f"\nsubsection Output\n  set Directory = {two}"
                "\nend\n")
    mpirun = shutil.which("mpirun") or shutil.which("mpiexec")
    result = subprocess.run([mpirun, "--allow-run-as-root", "--oversubscribe",
                             "-np", "2", LIFTOFF, two + ".prm"],
                            capture_output=True, text=True)
    check(result.returncode == 0, f"two ranks run ({result.stderr.strip()})")
    other = read_profile(two)
    same = len(other) == len(rows) and all(
        a["joint"] == b["joint"] and a["s"] == b["s"] for a, b in
        zip(rows, other))
    check(same, "two ranks: the same points in the same order")
    if same:
        worst = max(abs(float(a[c]) - float(b[c]))
                    / max(abs(float(a[c])), 1e-12)
                    for a, b in zip(rows, other)
                    for c in ("w_lower", "w_upper", "shear"))
        check(worst < 1e-8, f"two ranks: within {worst:.1e} of one rank's")


with tempfile.TemporaryDirectory() as work:
    static_profile(work)
    resumed_and_two_ranks(work)
finish()
