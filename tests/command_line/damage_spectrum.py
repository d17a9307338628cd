#!/usr/bin/python3
"""scripts/liftoff-damage's total against a sum made here, from the runs'
own history.csv, over axle loads, temperature bins and wander positions.

    damage_spectrum.py LIFTOFF LIFTOFF_DAMAGE

Two slabs 3 m x 2 m (Q2, 6 x 2 cells), a tensionless bed; a single axle at
60 and 100 kN and a tandem at 150 kN with their passes, two temperature
bins (dT = -8 K for 0.4 of the time, +8 K for 0.6, on top of a built-in
-3 K), three wander positions (sd 0.2 m), one speed: 18 dynamic runs of
50 steps. At each of 6 points and both faces the test sums

    passes x time share x wander weight x D(pass)

over the runs, with what it takes from each run's own files: the axle
load, the bin and the wheel path's y from used_parameters.prm and
history.csv (not from the tool's labels or tables), the wander weights by
hand (Gauss-Hermite with 3 points: 2/3 at the lane, 1/6 at +-sqrt(3) sd),
the face stresses as the eigenvalues of the bed-side stress tensor
(numpy's eigvalsh; the top face's tensor is minus it), and D(pass) by
Miner's sum under log10 N = 2 (MR / sigma)^1.22 over cycles counted by
the rainflow below (ASTM E1049, written here apart from the tool's), and
by the pass's peak alone. Both must equal the tool's damage.csv to 1e-9.
The faces' stresses themselves: the larger of the two is liftoff's own
sigma_max (the largest tension on either face) in one pass run again with
it probed, at every step and point.
The same for --static with 3 positions (-5.5 and 5.5 m: every wheel off
the 6 m plate, the state without the vehicle; 0 m: the static run), and the static
total must differ from the dynamic one (the dynamic ringing counts).
"""

import csv
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "common"))
from checks import check, finish  # noqa: E402

LIFTOFF, TOOL = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.dirname(os.path.abspath(TOOL)))
from liftoff_runs import parse_parameters, read_table  # noqa: E402

SCENE = """subsection Units
  set System              = SI
  set Length              = 6
  set Width               = 2
  set Thickness           = 0.2
  set Young's modulus     = 30e9
  set Density             = 2400
  set Subgrade modulus    = 50e6
  set Dashpot coefficient = 1.7e4
end
subsection Plate
  set Poisson ratio = 0.15
end
subsection Foundation
  set Model = tensionless
end
subsection Discretization
  set Cells along x     = 6
  set Cells along y     = 2
  set Polynomial degree = 2
end
subsection Slabs
  set Slabs along x   = 2
  set Shear stiffness = 5e8
end
subsection Loads
  subsection Vehicle 1
    set Wheel shape = disc
    set Wheel size  = 0.15
  end
end
"""
PASSES = {60e3: 2e5, 100e3: 5e4, 150e3: 4e4}
BINS = {-8.0: 0.4, 8.0: 0.6}
BUILT_IN = -3.0
SD, LANE = 0.2, -0.3
WANDER = {0.0: 2 / 3, math.sqrt(3) * SD: 1 / 6, -math.sqrt(3) * SD: 1 / 6}
POINTS = [(x, y) for y in (-0.8, 0.7) for x in (-1.6, -0.3, 1.2)]
MR = 3.5e6
DESCRIPTION = {
    "scene": "template.prm",
    "path": {"start": -5.5, "end": 5.5, "lane": LANE},
    "axles": [{"name": "single", "wheels": "0, 0.8, 0.5; 0, -0.8, 0.5",
               "loads": [[60e3, 2e5], [100e3, 5e4]]},
              {"name": "tandem", "wheels": "0, 0.8, 0.25; 0, -0.8, 0.25; "
               "-1.3, 0.8, 0.25; -1.3, -0.8, 0.25",
               "loads": [[150e3, 4e4]]}],
    "speeds": [[40, 1]],
    "temperature": {"expansion": 1e-5, "built-in": BUILT_IN,
                    "bins": [[-8, 0.4], [8, 0.6]]},
    "wander": {"sd": SD, "positions": 3},
    "points": {"x": [-1.6, -0.3, 1.2], "y": [-0.8, 0.7]},
    "law": {"MR": MR},
    "time step": 4e-3,
    "static positions": 3}


def rainflow(series):
    """ASTM E1049-85 5.4.4 as (peak, count) pairs, written apart from the
    tool's: the reversals by a walk, then the points kept in a list."""
    turning = []
    for v in series:
        if turning and v == turning[-1]:
            continue
        if len(turning) >= 2 and (turning[-1] - turning[-2]) * (
                v - turning[-1]) > 0:
            turning[-1] = v
        else:
            turning.append(v)
    kept, counted = [], []
    for v in turning:
        kept.append(v)
        while len(kept) > 2 and abs(kept[-1] - kept[-2]) >= abs(
                kept[-2] - kept[-3]):
            a, b = kept[-3], kept[-2]
            if len(kept) == 3:
                counted.append((max(a, b), 0.5))
                kept = kept[1:]
            else:
                counted.append((max(a, b), 1.0))
                kept = kept[:-3] + kept[-1:]
    counted += [(max(a, b), 0.5) for a, b in zip(kept, kept[1:])]
    return counted


def miner(counted):
    return sum(n * 10 ** (-2 * (MR / s) ** 1.22) for s, n in counted
               if s > 0)


def faces(row_stresses):
    """(bed-side, top) largest principal stress of each row."""
    out = []
    for sxx, syy, sxy in row_stresses:
        low, high = np.linalg.eigvalsh([[sxx, sxy], [sxy, syy]])
        out.append((high, -low))
    return np.array(out)


def stresses(history, point):
    names = ["%s(%r;%r)" % (q, *point) for q in ("sigma_xx", "sigma_yy",
                                                  "sigma_xy")]
    columns = []
    for name in names:
        match = [c for c in history.columns if c.replace(" [Pa]", "")
                 .replace(" ", "") == name.replace(" ", "")]
        columns.append(history[match[0]].to_numpy())
    return list(zip(*columns))


def run_facts(directory):
    """What a run was, from its own files: the axle load, the bin's dT,
    the built-in dT, the wheel path's y, static or not."""
    used = parse_parameters(os.path.join(directory, "used_parameters.prm"))
    history = read_table(os.path.join(directory, "history.csv"))
    return {"load": float(used["Loads/Vehicle 1/Magnitude"]),
            "dT": float(used["Loads/Temperature load 1/Magnitude"]),
            "built_in": float(used["Loads/Temperature load 2/Magnitude"]),
            "wheels": used["Loads/Vehicle 1/Wheels"],
            "static": used.get("Analysis/Type") == "static",
            # A run without the vehicle has no vehicle columns.
            "y": float(history.get("vehicle_1_y [m]", [math.nan])[0]),
            "x": float(history.get("vehicle_1_x [m]", [math.nan])[0]),
            "history": history}


def weight(facts):
    offset = facts["y"] - LANE
    wander = [w for o, w in WANDER.items() if abs(o - offset) < 1e-9]
    check(len(wander) == 1, "the run at y = %.6f m is a wander position of "
          "the hand rule" % facts["y"])
    return PASSES[facts["load"]] * BINS[facts["dT"]] * wander[0]


def tool_table(folder):
    with open(os.path.join(folder, "damage.csv")) as f:
        return {(float(r["x"]), float(r["y"]), r["face"]):
                (float(r["damage"]), float(r["damage_peak"]))
                for r in csv.DictReader(f)}


def compare(folder, hand, what):
    tool = tool_table(folder)
    worst = 0.0
    for key, (d, peak) in hand.items():
        t = tool[key]
        for mine, theirs in ((d, t[0]), (peak, t[1])):
            worst = max(worst, abs(mine - theirs) / max(abs(mine), 1e-300))
    largest = max(d for d, _ in hand.values())
    check(worst <= 1e-9 and largest > 1e-6,
          "%s: the tool's damage at %d points and faces equals the hand sum "
          "(largest relative difference %.2g; largest damage %.4g)"
          % (what, len(hand), worst, largest))
    return hand


def dynamic_sum(folder):
    hand = {(x, y, f): [0.0, 0.0] for x, y in POINTS
            for f in ("bed-side", "top")}
    runs = 0
    for entry in sorted(os.scandir(os.path.join(folder, "runs")),
                        key=lambda e: e.name):
        facts = run_facts(entry.path)
        runs += 1
        check(facts["built_in"] == BUILT_IN, "%s: the built-in dT is %g"
              % (entry.name, facts["built_in"]))
        w = weight(facts)
        for point in POINTS:
            series = faces(stresses(facts["history"], point))
            for k, face in enumerate(("bed-side", "top")):
                s = series[:, k]
                hand[(*point, face)][0] += w * miner(rainflow(s))
                hand[(*point, face)][1] += w * miner([(s.max(), 1.0)])
    check(runs == len(PASSES) * len(BINS) * len(WANDER),
          "dynamic: %d runs, one per axle load, bin and wander position"
          % runs)
    return compare(folder, {k: tuple(v) for k, v in hand.items()},
                   "dynamic")


def sigma_max_check(folder):
    """The faces' largest principal stresses against liftoff's own
    sigma_max, "the largest tension on either face", which takes each
    face's stress itself (doc/model.md): one pass run again with sigma_max
    probed too (night: the bin of -8 K on the built-in -3 K)."""
    run = os.path.join(folder, "runs", "single-100kN-dT-8-w1-v40")
    with open(os.path.join(run, "scene.prm")) as f:
        text = f.read()
    again = os.path.join(folder, "sigma_max")
    probes = ", ".join("%s(%r; %r)" % (q, *p) for p in POINTS
                       for q in ("sigma_xx", "sigma_yy", "sigma_xy",
                                 "sigma_max"))
    text += ("\nsubsection Output\n  set Probe quantities = %s\n"
             "  set Directory = %s\nend\n" % (probes, again))
    done = subprocess.run([LIFTOFF, "-"], input=text, capture_output=True,
                          text=True)
    check(done.returncode == 0, "the pass run again with sigma_max probes")
    history = read_table(os.path.join(again, "history.csv"))
    worst, scale = 0.0, 0.0
    for point in POINTS:
        both = faces(stresses(history, point)).max(axis=1)
        column = [c for c in history.columns
                  if c.startswith("sigma_max(%r;%r)" % point)][0]
        liftoff = history[column].to_numpy()
        worst = max(worst, float(np.abs(both - liftoff).max()))
        scale = max(scale, float(np.abs(liftoff).max()))
    check(worst <= 1e-6 * scale, "the larger of the two faces' principal "
          "stresses is liftoff's sigma_max at every step and point (%.2g "
          "Pa of %.4g MPa)" % (worst, scale / 1e6))


def static_sum(folder):
    """A static pass: [base, base, at x = 0, base, base] (the positions -5.5
    and 5.5 m leave every wheel off the 6 m plate)."""
    facts = [run_facts(e.path)
             for e in os.scandir(os.path.join(folder, "runs"))]
    bases = {f["dT"]: f for f in facts if f["load"] == 0}
    loaded = [f for f in facts if f["load"] > 0]
    check(len(bases) == 2 and len(loaded) == 18 and all(
        f["static"] and f["x"] == 0 for f in loaded),
        "static: a run without the vehicle per bin and one at x = 0 per "
        "pass (%d, %d)" % (len(bases), len(loaded)))
    hand = {(x, y, f): [0.0, 0.0] for x, y in POINTS
            for f in ("bed-side", "top")}
    for f in loaded:
        w = weight(f)
        for point in POINTS:
            base = faces(stresses(bases[f["dT"]]["history"], point))[0]
            at = faces(stresses(f["history"], point))[0]
            for k, face in enumerate(("bed-side", "top")):
                s = [base[k], base[k], at[k], base[k], base[k]]
                hand[(*point, face)][0] += w * miner(rainflow(s))
                hand[(*point, face)][1] += w * miner([(max(s), 1.0)])
    return compare(folder, {k: tuple(v) for k, v in hand.items()}, "static")


def main():
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "template.prm"), "w") as f:
            f.write(SCENE)
        description = os.path.join(work, "spectrum.json")
        with open(description, "w") as f:
            f.write(__import__("json").dumps(DESCRIPTION, indent=1))
        results = {}
        for mode in ("dynamic", "static"):
            folder = os.path.join(work, mode)
            command = [sys.executable, TOOL, description, "--executable",
                       LIFTOFF, "--output", folder, "--jobs", "2",
                       "--no-plot"] + (["--static"] if mode == "static"
                                       else [])
            done = subprocess.run(command, capture_output=True, text=True)
            check(done.returncode == 0, "%s: the tool ran (exit %d) %s"
                  % (mode, done.returncode, done.stderr.strip()[-300:]))
            if done.returncode != 0:
                continue
            results[mode] = (dynamic_sum if mode == "dynamic"
                             else static_sum)(folder)
            if mode == "dynamic":
                sigma_max_check(folder)
        if len(results) == 2:
            key = max(results["dynamic"],
                      key=lambda k: results["dynamic"][k][0])
            check(results["static"][key][0] != results["dynamic"][key][0],
                  "the static total differs from the dynamic one at the "
                  "critical point %s: %.4g against %.4g"
                  % (key, results["static"][key][0],
                     results["dynamic"][key][0]))
    finish()


main()
