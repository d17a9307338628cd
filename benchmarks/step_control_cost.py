#!/usr/bin/env python3
"""Fixed steps beside Time step control = error on Example 3
(prm/example-3-square-plate.prm, doc/model.md, "Time steps chosen by their
error"): steps taken and repeated, factorisations and their time, wall time
and the largest error of w(0,0) over the rows at the multiples of 2e-3,
relative to its largest value, against a run with dtau = 3.125e-5.

    /usr/bin/python3 benchmarks/step_control_cost.py build/liftoff

prints the table as markdown rows; about 2 minutes.
"""

import os
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "common"))
from scenes import read_history  # noqa: E402

LIFTOFF = sys.argv[1]
SCENE = os.path.join(os.path.dirname(__file__), "..", "prm",
                     "example-3-square-plate.prm")


def run(work, name, time_lines):
    """Run Example 3 with `time_lines` in Time integration; its history and
    summary text."""
    folder = os.path.join(work, name)
    with open(SCENE) as f:
        text = f.read()
    text += (f"subsection Time integration\n{time_lines}\nend\n"
             f"subsection Output\n  set Directory = {folder}\n"
             "  set VTU interval = 0\n  set Profile times =\nend\n")
    with open(folder + ".prm", "w") as f:
        f.write(text)
    subprocess.run([LIFTOFF, folder + ".prm"], check=True,
                   capture_output=True)
    with open(os.path.join(folder, "summary.txt")) as f:
        return read_history(folder), f.read()


def value(summary, key):
    """A summary line's number (a section time when indented), 0 if none."""
    match = re.search(r"^\s*" + re.escape(key) + r": (\S+)", summary, re.M)
    return float(match.group(1)) if match else 0.0


with tempfile.TemporaryDirectory() as work:
    reference, _ = run(work, "reference", "  set Time step = 3.125e-5")
    times = {round(t / 3.125e-5): w
             for t, w in zip(reference["tau"], reference["w(0;0)"])}
    scale = np.max(np.abs(reference["w(0;0)"]))

    def error(history):
        return max(abs(w - times[round(t / 3.125e-5)])
                   for t, w in zip(history["tau"], history["w(0;0)"])) / scale

    print("| run | steps (repeated) | factorisations | factorisation [s] "
          "| wall [s] | error |")
    print("|---|---|---|---|---|---|")
    for dt in ("2e-3", "1e-3", "5e-4", "2.5e-4", "1.25e-4"):
        history, summary = run(work, "fixed" + dt, f"  set Time step = {dt}")
        print(f"| fixed {dt} | {value(summary, 'steps'):.0f} "
              f"| {value(summary, 'factorisations'):.0f} "
              f"| {value(summary, 'factorisation'):.2f} "
              f"| {value(summary, 'wall time [s]'):.1f} "
              f"| {error(history):.2e} |")
    for tolerance in ("1e-2", "1e-3", "1e-4", "1e-5"):
        history, summary = run(
            work, "error" + tolerance,
            "  set Time step = 2e-3\n  set Time step control = error\n"
            f"  set Error tolerance = {tolerance}\n"
            "  set Finest step level = 5")
        print(f"| error {tolerance} "
              f"| {value(summary, 'time steps taken'):.0f} "
              f"({value(summary, 'time steps repeated'):.0f}) "
              f"| {value(summary, 'factorisations'):.0f} "
              f"| {value(summary, 'factorisation'):.2f} "
              f"| {value(summary, 'wall time [s]'):.1f} "
              f"| {error(history):.2e} |")
