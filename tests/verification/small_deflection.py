"""The small-deflection check of SI scenes against the closed form of a
free slab on a bilateral bed under its own weight: statically the slab
sinks w = rho g H / k everywhere, so the summary's largest |w| / thickness
must be rho g / k. A dynamic run starts settled under the weight; a
pressure rho g H added suddenly swings it from w_s to 3 w_s (w = w_s (2 -
cos omega t), which the trapezoidal rule keeps without decay). Above 0.2 of the thickness the run must end `completed with
warnings`, naming Units/Thickness; below, `completed`. A dimensionless
scene, whose force scale is free, is not checked."""

import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import prm_text, run_scene_or_fail  # noqa: E402

liftoff = sys.argv[1]
RHO, G, H, LENGTH = 2000.0, 9.81, 0.2, 4.0
RATIO_KEY = "largest |w| / thickness"


def si_slab(k, analysis, loads=None):
    """An SI slab under its own weight on a bilateral bed of modulus k."""
    return prm_text({"Loads": loads or {},
        "Units": {"System": "SI", "Length": LENGTH, "Thickness": H,
                  "Young's modulus": 30e9, "Density": RHO, "Gravity": G,
                  "Subgrade modulus": k},
        "Foundation": {"Model": "bilateral"},
        "Discretization": {"Cells along x": 4, "Cells along y": 4},
        "Analysis": analysis,
        "Time integration": {"Time step": 1e-3, "End time": 0.22},
        "Output": {"VTU interval": 0, "Write energies": "false"}}) + "\n"


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


with tempfile.TemporaryDirectory() as work:
    for k, share in ((RHO * G / 0.3, 0.3), (RHO * G / 0.1, 0.1)):
        name = "static_%g" % share
        s = summary(run_scene_or_fail(liftoff, work, name,
                                      si_slab(k, {"Type": "static"})))
        ratio = s[RATIO_KEY]
        check(abs(ratio - share) < 1e-9 * share,
              "%s: largest |w| / H = %.12g, rho g / k = %g" % (name, ratio,
                                                               share))
        warned = share > 0.2
        check(s["status"] == ("completed with warnings" if warned
                              else "completed"),
              "%s: status <%s>" % (name, s["status"]))
        check(("Units/Thickness" in s.get("warning", "")) == warned,
              "%s: warning <%s>" % (name, s.get("warning", "")))

    # The swing reaches 3 rho g / k = 0.3 at omega t = pi, t = pi sqrt(rho
    # H / k) = 0.2006 s for k = rho g / 0.1.
    pressure = {"Pressure 1": {"Region": "whole plate",
                               "Magnitude": RHO * G * H}}
    s = summary(run_scene_or_fail(liftoff, work, "dynamic",
                                  si_slab(RHO * G / 0.1, {"Type": "dynamic"},
                                          pressure)))
    ratio = s[RATIO_KEY]
    check(abs(ratio - 0.3) < 3e-3,
          "dynamic: largest |w| / H = %.6g, 3 rho g / k = 0.3" % ratio)
    check(s["status"] == "completed with warnings",
          "dynamic: status <%s>" % s["status"])

    s = summary(run_scene_or_fail(
        liftoff, work, "dimensionless",
        prm_text({"Analysis": {"Type": "static"},
                  "Foundation": {"Model": "bilateral"},
                  "Loads": {"Self weight": 1e6},
                  "Output": {"VTU interval": 0}}) + "\n"))
    check(RATIO_KEY not in s and s["status"] == "completed",
          "dimensionless: not checked (status <%s>)" % s["status"])
finish()
