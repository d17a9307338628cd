#!/usr/bin/python3
"""The tables of doc/studies.md, "Fatigue damage: dynamic against static,
...", from the folders doc/damage/study.sh wrote.

    /usr/bin/python3 doc/damage/study_table.py STUDY_FOLDER

Per folder (a way of computing: dynamic or static, bed, discretisation)
and temperature bin: the largest damage of one pass over the points and
faces, where, and the largest peak tension; then each discretisation's
change against the base run of the same way.
"""

import csv
import os
import re
import sys

FOLDERS = ["dynamic", "static", "dynamic-bilateral", "static-bilateral",
           "dynamic-half-step", "dynamic-fine", "static-half-spacing",
           "static-fine"]
# Each refinement against the run it refines.
REFINED = {"dynamic-half-step": "dynamic", "dynamic-fine": "dynamic",
           "static-half-spacing": "static", "static-fine": "static"}


def passes(folder):
    """The rows of pass_damage.csv with the pass's temperature bin."""
    with open(os.path.join(folder, "pass_damage.csv")) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["dT"] = re.search(r"-dT([-+][0-9.e+]+)-w", r["pass"]).group(1)
    return rows


def bins(folder):
    """{dT: (largest damage, x, y, face, largest peak tension)} over the
    points and faces (one pass per bin in the study)."""
    result = {}
    rows = passes(folder)
    for dt in {r["dT"] for r in rows}:
        mine = [r for r in rows if r["dT"] == dt]
        worst = max(mine, key=lambda r: float(r["damage"]))
        result[dt] = (float(worst["damage"]), worst["x"], worst["y"],
                      worst["face"],
                      max(float(r["peak_tension"]) for r in mine))
    return result


def at(folder, dt, x, y, face):
    """(damage, peak tension) of the bin's pass at the point and face."""
    for r in passes(folder):
        if (r["dT"], r["x"], r["y"], r["face"]) == (dt, x, y, face):
            return float(r["damage"]), float(r["peak_tension"])
    return None


def main(root):
    found = {f: bins(os.path.join(root, f)) for f in FOLDERS
             if os.path.exists(os.path.join(root, f, "pass_damage.csv"))}
    print("| way | dT [K] | largest damage of a pass | at x, y [m], face | "
          "largest peak tension [MPa] |")
    print("|---|---|---|---|---|")
    for f, table in found.items():
        for dt, (d, x, y, face, peak) in sorted(table.items(),
                                                key=lambda i: float(i[0])):
            print("| %s | %s | %.3g | %s, %s, %s | %.3f |"
                  % (f, dt, d, x, y, face, peak / 1e6))
    print()
    print("| refinement | dT [K] | damage at the base's critical point: "
          "base, refined, change | peak tension there [MPa]: base, "
          "refined, change |")
    print("|---|---|---|---|")
    for f, base in REFINED.items():
        if f not in found or base not in found:
            continue
        for dt, (d, x, y, face, _) in sorted(found[base].items(),
                                             key=lambda i: float(i[0])):
            b = at(os.path.join(root, base), dt, x, y, face)
            r = at(os.path.join(root, f), dt, x, y, face)
            print("| %s | %s | %.3g, %.3g, %+.1f %% | %.3f, %.3f, %+.2f %% |"
                  % (f, dt, b[0], r[0], 100 * (r[0] / b[0] - 1) if b[0]
                     else float("nan"), b[1] / 1e6, r[1] / 1e6,
                     100 * (r[1] / b[1] - 1) if b[1] else float("nan")))


main(sys.argv[1])
