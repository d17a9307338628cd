#!/usr/bin/env python3
"""The tutorial's scenes (doc/tutorial.md, prm/tutorial-*.prm) and its
commands run, shortened, and each answers a check it can be held to:

1. tutorial-1-first-slab, made static with the wheel held (Analysis/Type =
   static, the pulse's Time history = 1): the bed carries the wheel and the
   slab's weight, resultant = 50 kN + rho g H L W = 197150 N, and its centre
   lies where their moments balance, y = 50 kN x 2.25 m / 197150 N =
   0.5706 m (x = 0); to 1e-6.
2. tutorial-2-jointed-truck, cut at 20 ms: at t = 0 (the night curl and the
   weight, settled; the truck's load ramps in from 0) the bed carries the
   weight alone, rho g H L W = 286060 N (to 1e-6), and the curled slabs are
   symmetric about x = 0: w at the probes beside joint x1 equals w at their
   mirror images beside x2 (to 1e-9 of the largest |w|); the run's energy
   balance error stays below 1e-3 of its energy scale.
3. tutorial-3-deflectometer (whole, 60 ms) and
   `scripts/liftoff-backcalc --histories` on its history.csv with the scene
   as template, from the included scene's E = 30 GPa, k = 50 MPa/m: the
   fit returns the 35 GPa and 40 MPa/m the test was run with (to 1e-4).
4. `scripts/liftoff-study` on tutorial-4-study over 8 and 16 cells: the
   peak of max_M_1 it reports for 16 cells equals the largest max_M_1 of a
   run of the scene itself (to 1e-9), it comes during the pulse (t < 10
   ms), and the two meshes differ by less than 1 % (0.34 % measured), as
   the tutorial says.
5. pavement-engineer, the engineer's scene: 40 lines or fewer (issue 65),
   cut at 0.25 s (the tandem has rolled onto the curled free end), against
   the same scene with every value it leaves to the SI defaults written out
   here (concrete's density, nu and alpha, the dowels' steel, support and
   spacing, the tyres' pressure and discs, the plate's size from the
   slabs', the stress extremes): the same history.csv to the byte, and a
   summary.json with the largest tension of each face in MPa.

    tutorial_scenes.py LIFTOFF SOURCE_DIR
"""

import csv
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
from checks import check, finish  # noqa: E402
from liftoff_runs import (parse_summary, read_csv, run_scene,  # noqa: E402
                          scene_including)

PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") \
    else sys.executable
RHO_G = 2400 * 9.81


def read_rows(path):
    """history.csv as dicts of floats; a load transfer efficiency is empty
    while no load is near its joint (None then)."""
    with open(path) as f:
        return [{k: float(v) if v else None for k, v in row.items()}
                for row in csv.DictReader(f)]


def close(a, b, tolerance):
    return abs(a - b) <= tolerance * max(abs(b), 1e-300)


def first_slab(liftoff, prm, work):
    out = os.path.join(work, "tutorial-1")
    run_scene(liftoff, scene_including(
        os.path.join(prm, "tutorial-1-first-slab.prm"), [
            "Analysis/Type=static",
            "Loads/Patch load 1/Time history=1",
            "Output/VTU interval=0"], out), out)
    row = read_csv(os.path.join(out, "history.csv"))[-1]
    weight = RHO_G * 0.25 * 5 * 5
    load = 50e3
    resultant = row["resultant [N]"]
    centre = load * 2.25 / (load + weight)
    check(close(resultant, load + weight, 1e-6),
          "tutorial-1, static: the bed's resultant %.6g N = wheel + weight "
          "%.6g N" % (resultant, load + weight))
    check(close(row["resultant_y [m]"], centre, 1e-6)
          and abs(row["resultant_x [m]"]) < 1e-9,
          "tutorial-1, static: the resultant's centre (%.6g, %.6g) m where "
          "the moments balance, (0, %.6g) m" % (
              row["resultant_x [m]"], row["resultant_y [m]"], centre))


def jointed_truck(liftoff, prm, work):
    out = os.path.join(work, "tutorial-2")
    run_scene(liftoff, scene_including(
        os.path.join(prm, "tutorial-2-jointed-truck.prm"), [
            "Time integration/End time=0.02",
            "Output/Write foundation resultant=true",
            "Output/Profile times="], out), out)
    first = read_rows(os.path.join(out, "history.csv"))[0]
    weight = RHO_G * 0.25 * 13.5 * 3.6
    check(close(first["resultant [N]"], weight, 1e-6),
          "tutorial-2, t = 0: the bed's resultant %.6g N = the weight %.6g N "
          "(the truck's load ramps in from 0)" % (first["resultant [N]"],
                                                  weight))
    pairs = (("w(-2.2501;-1.6) [m]", "w(2.2501;-1.6) [m]"),
             ("w(-2.2499;-1.6) [m]", "w(2.2499;-1.6) [m]"))
    scale = max(abs(first[c]) for pair in pairs for c in pair)
    asymmetry = max(abs(first[a] - first[b]) for a, b in pairs) / scale
    check(asymmetry < 1e-9,
          "tutorial-2, t = 0: the curled slabs symmetric about x = 0 (w "
          "beside x1 against beside x2 differs by %.2g of max |w| = %.4g m)"
          % (asymmetry, scale))
    values, _ = parse_summary(os.path.join(out, "summary.txt"))
    balance = float(values[
        "energy balance error, largest share of the energy scale"])
    check(values["status"] == "completed" and balance < 1e-3,
          "tutorial-2: completed, energy balance error %.2g of its scale "
          "(< 1e-3)" % balance)


def deflectometer(liftoff, source, work):
    out = os.path.join(work, "tutorial-3")
    scene = os.path.join(source, "prm", "tutorial-3-deflectometer.prm")
    run_scene(liftoff, scene_including(scene, [], out), out)
    fit = os.path.join(work, "backcalc-3")
    result = subprocess.run(
        [PYTHON, os.path.join(source, "scripts", "liftoff-backcalc"),
         "--histories", os.path.join(out, "history.csv"), "--scene", scene,
         "--thickness", "0.25", "--poisson", "0.15", "--executable",
         liftoff, "--start", "30e9,50e6", "--tolerance", "1e-5",
         "--output", fit, "--no-plot"],
        capture_output=True, text=True)
    fitted = [line for line in result.stdout.splitlines()
              if line.startswith("fitted:")]
    ok = result.returncode == 0 and len(fitted) == 1
    e = k = float("nan")
    if ok:
        words = fitted[0].replace(",", " ").split()
        e = float(words[words.index("E") + 2])
        k = float(words[words.index("k") + 2])
    said = (result.stdout + result.stderr).strip().splitlines()
    check(ok and close(e, 35e9, 1e-4) and close(k, 40e6, 1e-4),
          "tutorial-3: liftoff-backcalc --histories from 30 GPa, 50 MPa/m "
          "returns E = %.6g Pa, k = %.6g N/m^3 (run with 35e9, 40e6)%s"
          % (e, k, "" if ok else ": " + (said[-1] if said else "no output")))


def study(liftoff, source, work):
    scene = os.path.join(source, "prm", "tutorial-4-study.prm")
    folder = os.path.join(work, "study-4")
    result = subprocess.run(
        [PYTHON, os.path.join(source, "scripts", "liftoff-study"), scene,
         "--executable", liftoff,
         "--refine", "Discretization/Cells along x=8,16",
         "--refine", "Discretization/Cells along y=8,16",
         "--qoi", "peak:max_M_1 [N m/m]", "--no-plot", "--output", folder],
        capture_output=True, text=True)
    check(result.returncode == 0, "tutorial-4: liftoff-study runs (%s)"
          % (result.stderr.strip().splitlines()[-1:] or ["no message"])[0])
    if result.returncode != 0:
        return
    with open(os.path.join(folder, "study.csv")) as f:
        rows = {r["run"]: r for r in csv.DictReader(f)}
    name = "value:peak:max_M_1 [N m/m]"
    coarse, fine = float(rows["c8"][name]), float(rows["c16"][name])
    at = float(rows["c16"]["at:peak:max_M_1 [N m/m]"])
    out = os.path.join(work, "tutorial-4")
    run_scene(liftoff, scene_including(scene, [], out), out)
    direct = max(r["max_M_1 [N m/m]"]
                 for r in read_csv(os.path.join(out, "history.csv")))
    check(close(fine, direct, 1e-9),
          "tutorial-4: the study's peak for 16 cells %.9g N m/m = the "
          "scene's own run's largest max_M_1 %.9g N m/m" % (fine, direct))
    check(0 < at < 0.01 and abs(coarse / fine - 1) < 0.01,
          "tutorial-4: the largest moment comes during the pulse (t = %g s) "
          "and 8 and 16 cells differ by %.2f %% (< 1 %%)"
          % (at, 100 * abs(coarse / fine - 1)))


# prm/pavement-engineer.prm with every SI default it relies on written out,
# as the scene of 64 lines read before the defaults (00ab6ff).
ENGINEER_SPELLED_OUT = """subsection Units
  set System = SI
  set Length = 14.5
  set Width = 4.8
  set Thickness = 0.25
  set Young's modulus = 30e9
  set Density = 2400
  set Subgrade modulus = 50e6
end
subsection Plate
  set Poisson ratio = 0.15
end
subsection Foundation
  set Damping ratio = 0.05
end
subsection Discretization
  set Cells along x = 58
  set Cells along y = 8
  set Polynomial degree = 2
end
subsection Slabs
  set Slab lengths = 4.5, 5.5, 4.5
  set Slab widths = 1.2, 3.6
  set Shear stiffness = 5e8
  subsection Dowels
    set Joints = x1, x2
    set Spacing = 0.3
    set Diameter = 0.032
    set Steel modulus = 200e9
    set Modulus of dowel support = 407e9
    set Joint opening = 0.006
  end
end
subsection Loads
  subsection Temperature load 1
    set Magnitude = -10
    set Expansion coefficient = 1e-5
    set Permanent = true
  end
  subsection Vehicle 1
    set Axles = single, single, 50e3; tandem, dual, 80e3
    set Tyre pressure = 0.7e6
    set Wheel shape = disc
    set Group spacings = 5
    set Path = -7.45 + 20*t; 0.6
  end
end
subsection Time integration
  set Time step = 1e-3
  set End time = 0.25
end
subsection Output
  set Directory = %s
  set VTU interval = 0
  set Write stress extremes = true
end
"""


def engineer(liftoff, prm, work):
    scene = os.path.join(prm, "pavement-engineer.prm")
    with open(scene) as f:
        n_lines = len(f.read().splitlines())
    check(n_lines <= 40, "pavement-engineer: %d lines (<= 40)" % n_lines)
    short = os.path.join(work, "engineer")
    run_scene(liftoff, scene_including(scene, [
        "Time integration/End time=0.25", "Output/VTU interval=0"], short),
        short)
    spelled = os.path.join(work, "engineer-spelled-out")
    run_scene(liftoff, ENGINEER_SPELLED_OUT % spelled, spelled)
    histories = []
    for folder in (short, spelled):
        with open(os.path.join(folder, "history.csv"), "rb") as f:
            histories.append(f.read())
    check(histories[0] == histories[1] and len(histories[0]) > 0,
          "pavement-engineer: history.csv of the 40 lines = that of the "
          "scene with every SI default written out (%d and %d bytes)"
          % tuple(len(h) for h in histories))
    with open(os.path.join(short, "summary.json")) as f:
        summary = json.load(f)
    faces = [summary.get("largest tension, %s face" % face, {})
             for face in ("top", "bottom")]
    ok = all("sigma_1 [MPa]" in face and face["sigma_1 [MPa]"] > 0
             for face in faces)
    check(ok and " MPa, " in summary.get("largest tension", ""),
          "pavement-engineer: the summary gives each face's largest tension "
          "in MPa (top %s, bottom %s; %s)" % (
              faces[0].get("sigma_1 [MPa]"), faces[1].get("sigma_1 [MPa]"),
              summary.get("largest tension")))


def main(liftoff, source):
    liftoff = os.path.abspath(liftoff)
    prm = os.path.join(source, "prm")
    work = tempfile.mkdtemp(prefix="tutorial_scenes_")
    first_slab(liftoff, prm, work)
    jointed_truck(liftoff, prm, work)
    deflectometer(liftoff, source, work)
    study(liftoff, source, work)
    engineer(liftoff, prm, work)
    finish()


if __name__ == "__main__":
    main(sys.argv[1], os.path.abspath(sys.argv[2]))
