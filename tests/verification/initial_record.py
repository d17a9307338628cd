#!/usr/bin/env python3
"""The first row of a time integration is the settled state, with its own
contact set.

A slab curled off its bed (Initial gap 0.2 (x^2 + y^2)) settles under its
weight onto the middle part of the bed before the time integration
starts. The history's row at tau = 0 must report that state: its
contact_fraction, resultant and contact_area equal those of a static run
of the same scene under the weight alone, and the resultant equals the
weight (equilibrium). A row 0 written with the first iterate's set (all
points in contact) reads a contact fraction of 1.

    initial_record.py LIFTOFF
"""

import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])

WEIGHT = 1.0
SCENE = {
    "Plate": {"Thickness ratio": 0.05, "Poisson ratio": 0.15},
    "Foundation": {"Model": "tensionless", "Stiffness": 100,
                   "Initial gap": "0.2*(x*x + y*y)"},
    "Discretization": {"Symmetry": "quarter", "Cells along x": 8,
                       "Cells along y": 8},
    "Loads": {"Self weight": WEIGHT},
    "Output": {"Write foundation resultant": "true"},
}

with tempfile.TemporaryDirectory() as work:
    static = read_history(run_scene_or_fail(LIFTOFF, work, "static",
                                            scene_text(SCENE, {
        "Analysis": {"Type": "static"}})))
    dynamic = read_history(run_scene_or_fail(LIFTOFF, work, "dynamic",
                                             scene_text(SCENE, {
        "Loads": {"Point load 1": {"Magnitude": 50, "Position": "0, 0",
                                   "Time history": "tau"}},
        "Time integration": {"Time step": 1e-3, "End time": 2e-3}})))
    share = static["contact_fraction"][-1]
    check(0.05 < share < 0.95, f"the settled slab bears on {share:.4f} of "
          "its bed")
    for column in ("contact_fraction", "resultant", "contact_area", "w(0;0)"):
        a, b = dynamic[column][0], static[column][-1]
        check(abs(a - b) <= 1e-9 * abs(b), f"row 0's {column} {a:.10g} "
              f"against the static settled state's {b:.10g}")
    check(abs(dynamic["resultant"][0] - WEIGHT) < 1e-9,
          f"row 0's resultant {dynamic['resultant'][0]:.12g} = the weight")
finish()
