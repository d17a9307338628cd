#!/usr/bin/env python3
"""The outputs of a joint: the profile along it (Output/Joint profiles,
joints.csv) and the load transfer at named points (Output/Joint probe
points, history.csv) against two rigid slabs solved here by hand, against
mirror symmetry and against the stress probes beside the joint; a resumed
and a two-rank run against the uninterrupted one-rank run.

Two slabs 0.5 x 1 side by side (joint x1 at x = 0) on a bilateral bed so
soft (Gamma = 1e-3) that each moves as a rigid body to about 1e-5, joined
by aggregate interlock AGG, a uniform pressure p on the left slab. Each
rigid slab has its centre's w and its slope along x (the y-symmetry
leaves no twist); the joint's springs add AGG B (J e e^T) with the jump
J = w_lower - w_upper at the faces, a 4 x 4 system. Checked along the
joint: w on both faces at every point, the shear per length AGG J, the
load transfer w_upper / w_lower, the points (the joint's Gauss points:
3 per face of the 8 Q2 faces, s in (0, 1), x = 0), and the history's
shear_x1 = AGG J B (the profile's forces add up to the joint's); the
named points' w_lower, w_upper and lte the same.

Named points also: loads mirrored about the joint give lte = lte_sigma =
1 and equal sides to round-off; a free joint passes nothing (lte 0, the
unloaded side's w and stress 0); each side's stress equals the stress
probe (Probe quantities, sigma_yy) 1e-7 inside that slab.

    joint_profile.py LIFTOFF
"""

import csv
import filecmp
import os
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
         "Output": {"Joint profiles": "true",
                    "Joint probe points": "0, 0.3; 0, 0.5"}})
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
    h = read_history(folder)
    for y in (0.3, 0.5):
        got = [h[f"{c}(0;{y:g})"][-1] for c in ("w_lower", "w_upper", "lte")]
        error = max(abs(got[0] - lower), abs(got[1] - upper)) / scale
        check(error < 1e-4 and abs(got[2] - upper / lower) < 1e-3,
              f"named point 0, {y:g}: w {got[0]:.6g}, {got[1]:.6g}, lte "
              f"{got[2]:.6f} against the rigid slabs' (error {error:.1e})")
    total = h["shear_x1"][-1]
    error = abs(total - exact * B) / abs(exact * B)
    check(error < 1e-3, f"history's shear_x1 = {total:.6g} against AGG J B "
          f"(error {error:.1e})")


def named_points(work):
    def run(name, loads, agg):
        points = "0, 0.2; 0, 0.35"
        text = scene_text(
            {"Analysis": {"Type": "static"},
             "Foundation": {"Model": "bilateral", "Stiffness": 500},
             "Discretization": {"Cells along x": 8, "Cells along y": 8},
             "Slabs": {"Slabs along x": 2, "Shear stiffness": agg},
             "Loads": {f"Point load {k + 1}": {"Magnitude": 100,
                                               "Position": f"{x:g}, 0.25"}
                       for k, x in enumerate(loads)},
             "Output": {"Joint probe points": points,
                        "Probe points": "-1e-7, 0.2; 1e-7, 0.2",
                        "Probe quantities": "sigma_yy(-1e-7; 0.2), "
                                            "sigma_yy(1e-7; 0.2)"}})
        return read_history(run_scene_or_fail(LIFTOFF, work, name, text))

    h = run("mirrored", (-0.1, 0.1), 50)
    for y in ("0.2", "0.35"):
        worst = max(abs(h[f"lte(0;{y})"][-1] - 1),
                    abs(h[f"lte_sigma(0;{y})"][-1] - 1),
                    abs(h[f"w_lower(0;{y})"][-1] / h[f"w_upper(0;{y})"][-1]
                        - 1))
        check(worst < 1e-9, f"mirrored loads, 0, {y}: both sides alike, lte "
              f"and lte_sigma 1 (to {worst:.1e})")
    h = run("one side", (-0.1,), 50)
    for side, x in (("lower", "-1e-07"), ("upper", "1e-07")):
        a, b = h[f"sigma_{side}(0;0.2)"][-1], h[f"sigma_yy({x};0.2)"][-1]
        check(abs(a - b) < 1e-5 * abs(a), f"sigma_{side} = {a:.6g} against "
              f"the stress probe {b:.6g} inside its slab")
    check(0.05 < h["lte(0;0.2)"][-1] < 1, "AGG = 50 passes some load: lte "
          f"{h['lte(0;0.2)'][-1]:.4f}")
    h = run("free", (-0.1,), 0)
    check(h["w_upper(0;0.2)"][-1] == 0 and h["sigma_upper(0;0.2)"][-1] == 0
          and h["lte(0;0.2)"][-1] == 0 and h["lte_sigma(0;0.2)"][-1] == 0,
          "a free joint: the unloaded side at rest, lte and lte_sigma 0")


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
                    "Joint probe points": "0, -0.2; 0, 0.1",
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
    check(filecmp.cmp(os.path.join(whole, "history.csv"),
                      os.path.join(folder, "history.csv"), shallow=False),
          "resumed: history.csv (with the named points) byte for byte")
    two, result = run_scene(LIFTOFF, work, "two_ranks", dynamic(0.1),
                            ranks=2)
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
    h, g = read_history(whole), read_history(two)
    a = h["w_lower(0;-0.2)"] - h["w_lower(0;-0.2)"][0]
    b = h["w_upper(0;-0.2)"] - h["w_upper(0;-0.2)"][0]
    expected = np.where(np.abs(a) > np.abs(b), b / np.where(a == 0, 1, a),
                        a / np.where(b == 0, 1, b))
    # Given where the load is near (the larger side moves by a tenth of
    # the plate's largest change or more), empty where it is far.
    given = ~np.isnan(h["lte(0;-0.2)"])
    loaded = np.maximum(np.abs(a), np.abs(b)) > 0.5 * np.max(np.abs(a))
    error = np.max(np.abs(h["lte(0;-0.2)"] - expected)[given], initial=0)
    check(h["w_lower(0;-0.2)"][0] > 0 and error < 1e-9
          and np.all(given[loaded]),
          f"dynamic: lte of the changes since the settled rest at tau = 0 "
          f"(to {error:.1e} in {given.sum()} of {len(given)} rows; rest w "
          f"{h['w_lower(0;-0.2)'][0]:.4g})")
    # The transfers are ratios of these; before the load arrives they are
    # ratios of round-off.
    named = [c for c in h if c.startswith(("w_lower", "w_upper",
                                           "sigma_lower", "sigma_upper"))]
    worst = max(np.max(np.abs(h[c] - g[c])) / max(np.max(np.abs(h[c])),
                                                   1e-300) for c in named)
    check(len(named) == 8 and worst < 1e-8, f"two ranks: the {len(named)} "
          f"named points' columns within {worst:.1e} of one rank's")


with tempfile.TemporaryDirectory() as work:
    static_profile(work)
    named_points(work)
    resumed_and_two_ranks(work)
finish()
