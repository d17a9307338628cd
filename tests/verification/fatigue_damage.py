#!/usr/bin/env python3
"""Output/Fatigue damage (FatigueDamage) against an independent count of
liftoff's own stress history, and across a resume and two ranks:

- a dynamic SI scene (two slabs of 0.22 and 0.18 m on a tensionless bed,
  a 60 kN point force sin(2000 t), 20 steps) with the damage under the
  MEPDG law (MR = 2 MPa) and the probes sigma_1_top and sigma_1_bottom at
  three cell centres (output points of one cell only): the damage in
  damage.0000.vtu at each probe and face equals the rainflow count (ASTM
  E1049) and Miner's sum of the probe's own history.csv column made here
  by scripts/liftoff_fatigue.py, within 2e-7 (the field files hold 32-bit
  floats: 6e-8; a cycle counted wrong is off by far more); the same with
  the law as the expression 2.0*(MR/sigma)^1.22;
- the summary's largest damage (a double) is the largest value of the
  field to its 32 bits, at its point;
- the same scene on a bonded cement-treated base (0.15 m, E_b / E = 0.3)
  with the base's own law, the expression (0.972-sigma/MR)/0.0825 of
  MR_b = 0.8 MPa: the damage at the base's faces (damage_base_top,
  damage_base_bottom) equals the count of the probes sigma_1_base_top,
  sigma_1_base_bottom under that law, and the slab's faces the count under
  the slab's, within 2e-7; the summary's largest over the four faces is
  the field's, at its point;
- that run stopped at a checkpoint after step 10 and resumed writes the
  damage field (four faces) and summary entries of the run without a
  stop, to the bit;
- two ranks give the same largest damage's point, face and slab at each
  of the four faces, its value within 1e-12, and the field (its pieces
  joined, sorted by point) to its 32 bits.

    fatigue_damage.py LIFTOFF
"""

import json
import os
import sys
import tempfile

import meshio
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene, run_scene_or_fail, scene_text  # noqa: E402,E501
import liftoff_fatigue as fatigue  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])
MR = 2e6
# Centres of cells of 0.5 m (8 x 6 cells on 4 m x 3 m, centred at 0).
PROBES = [(0.75, 0.25), (1.25, 1.25), (-0.25, -0.75)]
FACES = ("top", "bottom")
BASE_FACES = FACES + ("base_top", "base_bottom")
MR_BASE = 0.8e6
BASE_LAW = "(0.972-sigma/MR)/0.0825"

SCENE = {
    "Units": {"System": "SI", "Length": 4, "Width": 3, "Thickness": 0.2,
              "Young's modulus": 30e9, "Density": 2400, "Gravity": 0,
              "Subgrade modulus": 50e6},
    "Plate": {"Poisson ratio": 0.3},
    "Foundation": {"Model": "tensionless"},
    "Slabs": {"Slabs along x": 2, "Thicknesses": "0.22, 0.18"},
    "Discretization": {"Cells along x": 8, "Cells along y": 6},
    "Linear solver": {"Direct solver package": "klu"},
    "Time integration": {"Time step": 5e-4, "End time": 0.01},
    "Loads": {"Point load 1": {"Magnitude": 60e3, "Position": "0.9, 0.4",
                               "Time history": "sin(2000*t)"}},
    "Output": {"Write energies": "false",
               "Probe quantities": ", ".join(
                   f"sigma_1_{face}({x}; {y})" for x, y in PROBES
                   for face in FACES),
               "Fatigue damage": {"Enable": "true",
                                  "Modulus of rupture": MR}}}

BASE_SCENE = {
    "Base": {"Interface": "bonded", "Thickness": 0.15, "Modulus ratio": 0.3,
             "Poisson ratio": 0.2, "Density ratio": 0.9},
    "Output": {"Probe quantities": ", ".join(
                   f"sigma_1_{face}({x}; {y})" for x, y in PROBES
                   for face in BASE_FACES),
               "Fatigue damage": {"Base modulus of rupture": MR_BASE,
                                  "Base expression": BASE_LAW}}}


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def damage_entries(folder):
    return {k: v for k, v in summary(folder).items() if "fatigue" in k}


def field(folder, pieces=1, faces=FACES):
    """The damage field's points and values per face, the pieces joined."""
    points, values = [], {face: [] for face in faces}
    for piece in range(pieces):
        mesh = meshio.read(os.path.join(folder, f"damage.{piece:04d}.vtu"))
        points.append(mesh.points[:, :2])
        for face in faces:
            values[face].append(mesh.point_data[f"damage_{face}"])
    return (np.concatenate(points),
            {face: np.concatenate(v) for face, v in values.items()})


def at_probes(folder, laws):
    """Worst relative difference between the field at each probe and the
    count of the probe's history here (under laws[face]), and the largest
    damage compared."""
    points, values = field(folder, faces=tuple(laws))
    history = read_history(folder)
    worst, largest = 0.0, 0.0
    for x, y in PROBES:
        at = np.flatnonzero(np.hypot(points[:, 0] - x, points[:, 1] - y)
                            < 1e-9)
        assert at.size == 1, f"{at.size} output points at ({x}, {y})"
        for face, law in laws.items():
            column = next(v for k, v in history.items()
                          if k.startswith(f"sigma_1_{face}({x:g};{y:g})"))
            cycles = fatigue.rainflow(column)
            counts = [c for _, _, c in cycles]
            reference = fatigue.damage(fatigue.peaks(cycles), counts, law)
            got = values[face][at[0]]
            largest = max(largest, reference)
            worst = max(worst, abs(got - reference) / max(reference, 1e-300))
    return worst, largest


def against_history(work):
    folder = run_scene_or_fail(LIFTOFF, work, "mepdg", scene_text(SCENE))
    worst, largest = at_probes(folder, slab_laws())
    check(worst < 2e-7 and largest > 1e-4,
          f"MEPDG law: the damage at {len(PROBES)} probes x 2 faces equals "
          "liftoff_fatigue.py's rainflow and Miner's sum of the probe's "
          f"history within {worst:.1e} (< 2e-7; largest {largest:.3g})")
    summary_is_field(folder, FACES)
    expression = run_scene_or_fail(LIFTOFF, work, "expression", scene_text(
        SCENE, {"Output": {"Fatigue damage": {
            "Law": "expression", "Expression": "2.0*(MR/sigma)^1.22"}}}))
    worst, _ = at_probes(expression, slab_laws())
    check(worst < 2e-7, "the law as the expression 2.0*(MR/sigma)^1.22: "
          f"the same damage at the probes within {worst:.1e}")


def slab_laws():
    return {face: fatigue.Law(MR) for face in FACES}


def summary_is_field(folder, faces):
    """The summary's largest damage over `faces` is the field's, at its
    point."""
    points, values = field(folder, faces=faces)
    entries = summary(folder)
    face = max(faces, key=lambda f: values[f].max())
    words = face.replace("_", " ")
    best = entries[f"largest fatigue damage, {words} face"]
    k = int(np.argmax(values[face]))
    check(abs(best["damage"] / values[face].max() - 1) < 1e-7
          and abs(best["x [m]"] - points[k, 0]) < 1e-12
          and abs(best["y [m]"] - points[k, 1]) < 1e-12
          and entries["largest fatigue damage"].split(", ")[1]
          == f"{words} face",
          f"the summary's largest damage {best['damage']:.6g} ({words} face) "
          f"is the field's largest over {len(faces)} faces, at its point")


def with_base(work):
    """The base's faces counted by the base's law; the slab's by its own."""
    folder = run_scene_or_fail(LIFTOFF, work, "base",
                               scene_text(SCENE, BASE_SCENE))
    laws = slab_laws()
    for face in ("base_top", "base_bottom"):
        laws[face] = fatigue.Law(MR_BASE, expression=BASE_LAW)
    worst, largest = at_probes(folder, laws)
    _, base_largest = at_probes(folder, {"base_bottom": laws["base_bottom"]})
    check(worst < 2e-7 and base_largest > 1e-4,
          "a bonded base with its own law: the damage at the probes x 4 "
          "faces equals liftoff_fatigue.py's count of the probes' "
          f"histories (the base's under {BASE_LAW}) within {worst:.1e} "
          f"(< 2e-7; largest at the base's bottom {base_largest:.3g})")
    summary_is_field(folder, BASE_FACES)
    return folder


def resumed_and_two_ranks(work, whole):
    scene = scene_text(SCENE, BASE_SCENE)
    stop = scene + "subsection Time integration\n  set End time = 0.005\n" \
        "end\nsubsection Checkpoint\n  set Interval = 10\nend\n"
    run_scene(LIFTOFF, work, "resumed", stop)
    folder, second = run_scene(LIFTOFF, work, "resumed", scene, ["--resume"])
    same = (second.returncode == 0
            and damage_entries(folder) == damage_entries(whole)
            and all(np.array_equal(field(folder, faces=BASE_FACES)[1][f],
                                   field(whole, faces=BASE_FACES)[1][f])
                    for f in BASE_FACES))
    check(same, "stopped after step 10 and resumed: the damage field and the "
          "summary's damage entries of the run without a stop, to the bit")
    folder, two = run_scene(LIFTOFF, work, "two_ranks", scene, ranks=2)
    if two.returncode != 0:
        print(two.stderr)
        check(False, "two ranks ran")
        return
    one_entries, two_entries = damage_entries(whole), damage_entries(folder)
    value = max(abs(one_entries[key]["damage"] - two_entries[key]["damage"])
                / max(abs(one_entries[key]["damage"]), 1e-300)
                for key in one_entries if isinstance(one_entries[key], dict))
    places = all({k: v for k, v in one_entries[key].items() if k != "damage"}
                 == {k: v for k, v in two_entries[key].items()
                     if k != "damage"}
                 for key in one_entries if isinstance(one_entries[key], dict))
    one_points, one_values = field(whole, faces=BASE_FACES)
    two_points, two_values = field(folder, pieces=2, faces=BASE_FACES)
    worst = 0.0
    for face in BASE_FACES:
        a = np.lexsort((one_values[face], one_points[:, 1], one_points[:, 0]))
        b = np.lexsort((two_values[face], two_points[:, 1], two_points[:, 0]))
        scale = max(np.abs(one_values[face]).max(), 1e-300)
        worst = max(worst, np.abs(one_values[face][a]
                                  - two_values[face][b]).max() / scale)
    check(places and value < 1e-12 and len(one_points) == len(two_points)
          and worst < 1e-7
          and sum(isinstance(v, dict) for v in one_entries.values()) == 4,
          "two ranks: the largest damage of each face at the same point and "
          f"slab, within {value:.1e} (< 1e-12); the field within {worst:.1e} "
          "of its largest (32 bits)")


with tempfile.TemporaryDirectory() as work:
    against_history(work)
    resumed_and_two_ranks(work, with_base(work))
finish()
