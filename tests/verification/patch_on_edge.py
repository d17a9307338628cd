#!/usr/bin/env python3
"""A pressure patch partly on the plate applies the pressure over the
part on it only, and a vehicle may start off the plate and drive on:

- static, bilateral bed, free plate: the bed's resultant equals p times
  the patch's area on the plate in closed form: a disc cut by the edge
  (the circular segment r^2 acos(e/r) - e sqrt(r^2 - e^2) off it, its
  centre inside, on and beyond the edge), a rectangle over a corner (the
  product of its overlaps), and the dual tyres of an axle (Axles) whose
  outer tyres hang over the edge;
- dynamic: a tandem on dual tyres whose path starts with every tyre off
  the plate is accepted, carries nothing until its first tyre reaches the
  edge, and ends with all its tyres on (history's vehicle_1_on).

    patch_on_edge.py LIFTOFF
"""

import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

P, HALF = 0.7e6, 2.0
SI = {
    "Units": {"System": "SI", "Length": 2 * HALF, "Thickness": 0.25,
              "Young's modulus": 30e9, "Density": 2400, "Gravity": 0,
              "Subgrade modulus": 50e6},
    "Plate": {"Poisson ratio": 0.15},
    "Foundation": {"Model": "bilateral"},
    "Analysis": {"Type": "static"},
    "Discretization": {"Cells along x": 8, "Cells along y": 8},
    "Output": {"Write foundation resultant": "true"},
}


def disc_on_plate(r, e):
    """The area of a disc of radius r on the side of a straight edge at
    which its centre lies at the signed distance e (< 0: beyond it)."""
    e = max(-r, min(r, e))
    off = r * r * math.acos(e / r) - e * math.sqrt(r * r - e * e)
    return math.pi * r * r - off


def resultant(work, name, loads):
    history = read_history(run_scene_or_fail(LIFTOFF, work, name, scene_text(
        SI, {"Loads": loads})))
    return history["resultant [N]"][-1]


def compare(what, value, area, pressure=P):
    force = pressure * area
    error = abs(value - force) / force
    check(error < 1e-9, f"{what}: bed resultant {value:.10g} N against p x "
          f"area on the plate {force:.10g} N: relative difference {error:.1e}")


def static_patches(work):
    r = 0.15
    for e in (0.05, 0.0, -0.1):
        value = resultant(work, f"disc_{e:g}", {"Patch load 1": {
            "Magnitude": P, "Shape": "disc", "Size": 2 * r,
            "Path": f"{HALF - e}; 0.3"}})
        compare(f"disc of diameter {2 * r} m, centre {e:+g} m inside the "
                "edge", value, disc_on_plate(r, e))
    value = resultant(work, "corner", {"Patch load 1": {
        "Magnitude": P, "Shape": "rectangle", "Size": "0.3, 0.2",
        "Path": f"{HALF - 0.05}; {HALF + 0.04}"}})
    compare("rectangle 0.3 x 0.2 m over a corner", value,
            (0.15 + 0.05) * (0.1 - 0.04))
    # An axle of dual tyres, 20 kN each at 0.5 MPa (radius 0.113 m), 3.9 m
    # track: the inner tyres on the plate, the outer ones' centres 0.05 m
    # beyond the edges y = +-2.
    load, track, dual, pressure = 80e3, 3.9, 0.2, 0.5e6
    value = resultant(work, "axle", {"Vehicle 1": {
        "Axles": f"single, dual, {load:g}", "Tyre pressure": pressure,
        "Track width": track, "Dual spacing": dual, "Wheel shape": "disc",
        "Path": "0.5; 0"}})
    radius = math.sqrt(load / 4 / pressure / math.pi)
    inner = HALF - (track - dual) / 2
    outer = HALF - (track + dual) / 2
    compare("dual tyres of an axle across the edges", value,
            2 * (disc_on_plate(radius, inner) + disc_on_plate(radius, outer)),
            pressure)


def driving_on(work):
    history = read_history(run_scene_or_fail(LIFTOFF, work, "entering",
                                             scene_text(SI, {
        "Analysis": {"Type": "dynamic"},
        "Foundation": {"Damping ratio": 0.05},
        "Loads": {"Vehicle 1": {
            "Axles": "tandem, dual, 80e3", "Tyre pressure": P,
            "Wheel shape": "disc", "Path": "-2.9 + 100*t; 0"}},
        "Time integration": {"Time step": 1e-3, "End time": 0.03}})))
    on = history["vehicle_1_on"]
    x = history["vehicle_1_x [m]"]
    radius = math.sqrt(20e3 / P / math.pi)
    front = x + 0.65 + radius
    first = next(k for k in range(len(on)) if on[k] > 0)
    check(on[0] == 0 and front[first] > -HALF >= front[first - 1],
          f"the tandem starts off the plate and its first tyre lands as its "
          f"edge crosses x = -2 m (t = {history['t [s]'][first]:.3f} s)")
    check(on[-1] == 8, f"all 8 tyres on the plate at the end ({on[-1]:g})")


with tempfile.TemporaryDirectory() as work:
    static_patches(work)
    driving_on(work)
finish()
