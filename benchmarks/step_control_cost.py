#!/usr/bin/env python3
"""Fixed steps beside Time step control = error on a scene of prm/
(doc/model.md, "Time steps chosen by their error"; doc/studies.md,
"Automatic time steps against fixed ones"): steps taken and repeated,
factorisations and their time, the run's CPU time (user + system, which
the load of a shared machine disturbs less than its wall time) and wall
time, and the largest error of the scene's quantity over the rows (at the
multiples of the largest step), relative to its largest value, against a
fixed-step run of a much smaller step h. That run's differences to the
runs at 2h and 4h are printed first: with an order of at least 1 its own
error is below the first. (Richardson's extrapolation is not used: the
order in dtau does not settle on these scenes, 0.25 to 0.8 between 4h, 2h
and h, as the thickness-shear modes and the lift-off keep the runs out of
the asymptotic range; doc/studies.md.)

    /usr/bin/python3 benchmarks/step_control_cost.py LIFTOFF [SCENE]

SCENE: example-3 (the default: Example 3, tau <= 0.2, w(0,0); about 2
minutes), example-1 (Example 1, tau <= 0.2, w(0,0); 30 s) or truck
(prm/truck-crossing-slab.prm to tau = 0.5, the truck then at the far edge,
w(0,0); about 3 minutes). Prints the table as markdown rows.
"""

import os
import re
import resource
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "common"))
from scenes import read_history  # noqa: E402

LIFTOFF = sys.argv[1]
PRM = os.path.join(os.path.dirname(__file__), "..", "prm")
# Per scene: its file, extra lines of Time integration, the quantity, the
# largest step (the rows), the fixed steps compared, the finest level and
# tolerances of the automatic runs, and the reference's step.
SCENES = {
    "example-3": ("example-3-square-plate.prm", "", "w(0;0)", 2e-3,
                  [2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4], 5,
                  ["1e-2", "1e-3", "1e-4", "1e-5"], 3.125e-5),
    "example-1": ("example-1-beam.prm", "", "w(0;0)", 2e-3,
                  [2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4], 5,
                  ["1e-2", "1e-3", "1e-4", "1e-5"], 3.125e-5),
    "truck": ("truck-crossing-slab.prm", "  set End time = 0.5", "w(0;0)",
              2.5e-3, [2.5e-3, 1.25e-3, 6.25e-4, 3.125e-4], 4,
              ["1e-2", "1e-3", "1e-4"], 1.5625e-4),
}
NAME = sys.argv[2] if len(sys.argv) > 2 else "example-3"
FILE, TIME_LINES, QOI, LARGEST, FIXED, FINEST, TOLERANCES, REFERENCE = \
    SCENES[NAME]


def run(work, name, time_lines):
    """Run the scene with `time_lines` in Time integration; its history,
    summary text and CPU time."""
    folder = os.path.join(work, name)
    with open(os.path.join(PRM, FILE)) as f:
        text = f.read()
    text += (f"subsection Time integration\n{TIME_LINES}\n{time_lines}\nend\n"
             f"subsection Output\n  set Directory = {folder}\n"
             "  set VTU interval = 0\n  set Profile times =\nend\n")
    with open(folder + ".prm", "w") as f:
        f.write(text)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([LIFTOFF, folder + ".prm"], check=True,
                   capture_output=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime
           - before.ru_utime - before.ru_stime)
    with open(os.path.join(folder, "summary.txt")) as f:
        return read_history(folder), f.read(), cpu


def value(summary, key):
    """A summary line's number (a section time when indented), 0 if none."""
    match = re.search(r"^\s*" + re.escape(key) + r": (\S+)", summary, re.M)
    return float(match.group(1)) if match else 0.0


def at_rows(history):
    """The quantity at the multiples of LARGEST, by their number."""
    return {round(t / LARGEST): w for t, w in zip(history["tau"],
                                                  history[QOI])
            if abs(t / LARGEST - round(t / LARGEST)) < 1e-6}


def row(name, history, summary, cpu, steps):
    return (f"| {name} | {steps} | {value(summary, 'factorisations'):.0f} "
            f"| {value(summary, 'factorisation'):.2f} | {cpu:.1f} "
            f"| {value(summary, 'wall time [s]'):.1f} "
            f"| {error(history):.2e} |")


with tempfile.TemporaryDirectory() as work:
    fine = [at_rows(run(work, f"reference{k}",
                        f"  set Time step = {k * REFERENCE}")[0])
            for k in (1, 2, 4)]
    reference = fine[0]
    scale = np.max(np.abs(list(reference.values())))
    d = [max(abs(fine[k][n] - reference[n]) for n in reference) / scale
         for k in (1, 2)]
    print(f"{NAME}, {QOI}: reference dtau = {REFERENCE:g}; its difference "
          f"to 2x and 4x that step: {d[0]:.1e}, {d[1]:.1e}")

    def error(history):
        rows = at_rows(history)
        return max(abs(rows[n] - reference[n]) for n in rows) / scale

    print("| run | steps (repeated) | factorisations | factorisation [s] "
          "| CPU [s] | wall [s] | error |")
    print("|---|---|---|---|---|---|---|")
    for dt in FIXED:
        history, summary, cpu = run(work, f"fixed{dt:g}",
                                    f"  set Time step = {dt:g}")
        print(row(f"fixed {dt:g}", history, summary, cpu,
                  f"{value(summary, 'steps'):.0f}"), flush=True)
    for tolerance in TOLERANCES:
        history, summary, cpu = run(
            work, "error" + tolerance,
            f"  set Time step = {LARGEST:g}\n"
            "  set Time step control = error\n"
            f"  set Error tolerance = {tolerance}\n"
            f"  set Finest step level = {FINEST}")
        print(row(f"error {tolerance}", history, summary, cpu,
                  f"{value(summary, 'time steps taken'):.0f} "
                  f"({value(summary, 'time steps repeated'):.0f})"),
              flush=True)
