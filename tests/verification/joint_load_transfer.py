#!/usr/bin/env python3
"""The load transfer efficiency of an aggregate-interlock joint against two
published fits of it as a function of the dimensionless joint stiffness
f = AGG / (k l), l = (D / k)^(1/4) the radius of relative stiffness.

Two 10 m x 5 m slabs side by side on a bilateral bed (the joint y = 0 is
10 m long, 9.5 l from the load to the far ends), a 40 kN disc load of
radius a = 0.15 m tangent to the joint; LTE = 100 w_unloaded / w_loaded,
w read at the joint's two faces under the load's centre. The fits:

- Crovetti (1994): LTE = 100 / (1 + 1.2 f^-0.849);
- Ioannides and Hammons (1996):
  LTE = 100 / (1 + 10^((0.214 - 0.183 a/l - log10 f) / 1.18))
(scripts/lte_fits.py, which scripts/liftoff-backcalc uses too).

Neither is exact (both fit finite element results over a range of a/l,
and they differ by up to 4 points); the check is liftoff within 5 points
of the nearer one at f = 0.1, 1, 10, 100, as the issue asks, and within
1.5 points of Ioannides and Hammons', whose fit carries a/l (measured:
0.9, 0.8, 1.2 and 0.8 points from it at the four f; 1.2 to 3.6 below
Crovetti's). The same runs with 80 cells along y change the LTE by less
than 0.03 points.

    joint_load_transfer.py LIFTOFF
"""

import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..",
                                "scripts"))
from checks import check, finish  # noqa: E402
from lte_fits import (crovetti, ioannides_hammons,  # noqa: E402
                      radius_of_relative_stiffness)
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

E, H, NU, K, A, P = 30e9, 0.25, 0.15, 50e6, 0.15, 40e3
ELL = radius_of_relative_stiffness(E, H, NU, K)


def liftoff_lte(work, f):
    """The LTE liftoff computes for the joint stiffness f: the load is on
    the slab y < 0, the half x >= 0 is modelled (the scene is symmetric
    about x = 0)."""
    text = scene_text({
        "Units": {"System": "SI", "Length": 10, "Width": 10, "Thickness": H,
                  "Young's modulus": E, "Density": 2400, "Gravity": 0,
                  "Subgrade modulus": K},
        "Plate": {"Poisson ratio": NU},
        "Analysis": {"Type": "static"},
        "Foundation": {"Model": "bilateral"},
        "Discretization": {"Symmetry": "half", "Cells along x": 20,
                           "Cells along y": 40},
        "Slabs": {"Slabs along y": 2, "Shear stiffness": f * K * ELL},
        "Loads": {"Patch load 1": {"Magnitude": P / (math.pi * A * A),
                                   "Path": f"0; {-A}", "Shape": "disc",
                                   "Size": 2 * A}},
        "Output": {"Probe points": "0, -1e-7; 0, 1e-7"}})
    folder = run_scene_or_fail(LIFTOFF, work, f"lte_{f}", text)
    history = read_history(folder)
    loaded, unloaded = history["w(0;-1e-07) [m]"][0], history["w(0;1e-07) [m]"][0]
    return 100 * unloaded / loaded


with tempfile.TemporaryDirectory() as work:
    print(f"l = {ELL:.4f} m, a / l = {A / ELL:.4f}")
    for f in [0.1, 1, 10, 100]:
        lte = liftoff_lte(work, f)
        fits = (crovetti(f), ioannides_hammons(f, A / ELL))
        print(f"f = {f:5g}: liftoff {lte:6.2f}, Crovetti {fits[0]:6.2f}, "
              f"Ioannides-Hammons {fits[1]:6.2f}")
        check(min(abs(lte - fit) for fit in fits) <= 5,
              f"f = {f}: LTE {lte:.2f} within 5 points of the nearer fit")
        check(abs(lte - fits[1]) <= 1.5,
              f"f = {f}: LTE {lte:.2f} within 1.5 points of Ioannides and "
              f"Hammons' {fits[1]:.2f}")
finish()
