#!/usr/bin/python3
"""The target-driven study beside the full ladder on the paper's Example 3,
Example 1 or the truck scene (doc/studies.md, "A study that stops at a
target").

    benchmarks/study_target.py LIFTOFF FOLDER [--scene SCENE] [TARGET ...]

SCENE: example-3 (the default: 4 meshes of p = 2 x 8 time steps, 32 runs,
about 5 minutes on two busy cores), example-1 (the beam: 4 meshes of p = 1
x 8 time steps, about 1 minute) or truck (prm/truck-crossing-slab.prm to
tau = 0.5: 3 meshes of p = 2 x 5 time steps, w(0;0)). Runs the full
ladder into FOLDER/full, then climbs it to each
TARGET (default 1e-2 3e-3 1e-3) into FOLDER/target-TARGET, each from
scratch, and prints a markdown table: the runs each climb made and their
process wall time, the chosen run, its estimated error and its true error
(against the finest run of the full ladder), and the full ladder's cheapest
run meeting the target by its true error (least process wall time, and
least unknowns x steps).
"""

import csv
import os
import re
import subprocess
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
TIME_STEPS = "2e-3,1e-3,5e-4,2.5e-4,1.25e-4,6.25e-5,3.125e-5,1.5625e-5"
SCENES = {
    "example-3": ("w(0.05;0)", [
        "prm/example-3-square-plate.prm",
        "--refine", "Discretization/Cells along x=4,8,16,32",
        "--refine", "Discretization/Cells along y=4,8,16,32",
        "--degrees", "2", "--time-steps", TIME_STEPS,
        "--set", "Time integration/End time=0.1",
        "--set", "Output/Probe points=0.05, 0; 0.15, 0"]),
    "example-1": ("w(0;0)", [
        "prm/example-1-beam.prm",
        "--refine", "Discretization/Cells along x=10,20,40,80",
        "--degrees", "1", "--time-steps", TIME_STEPS,
        "--set", "Time integration/End time=0.1"]),
    "truck": ("w(0;0)", [
        "prm/truck-crossing-slab.prm",
        "--refine", "Discretization/Cells along x=10,20,40",
        "--refine", "Discretization/Cells along y=5,10,20",
        "--degrees", "2",
        "--time-steps", "5e-3,2.5e-3,1.25e-3,6.25e-4,3.125e-4",
        "--set", "Time integration/End time=0.5"]),
}
QOI, LADDER = SCENES["example-3"]


def study(liftoff, output, *extra):
    return subprocess.run([os.path.join(ROOT, "scripts", "liftoff-study")]
                          + LADDER + ["--qoi", QOI] + ["--executable", liftoff, "--output",
                                      output, "--overwrite"] + list(extra),
                          cwd=ROOT, capture_output=True, text=True)


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def cheapest(full, target):
    """The full ladder's cheapest runs meeting target by their true error
    (the reference, error 0 by definition, left out)."""
    error = "error:" + QOI
    good = [r for r in full if 0 < float(r[error]) <= target]
    if not good:
        return "none"
    wall = min(good, key=lambda r: float(r["process_wall"]))
    work = min(good, key=lambda r: int(r["dofs"]) * int(r["steps"]))
    return "%s (%.2f s, %.2g); %s (%d unknowns x steps, %.2g)" % (
        wall["run"], float(wall["process_wall"]), float(wall[error]),
        work["run"], int(work["dofs"]) * int(work["steps"]),
        float(work[error]))


def climb_row(liftoff, folder, target, full):
    output = os.path.join(folder, "target-%g" % target)
    run = study(liftoff, output, "--target", repr(target))
    walls = [float(w) for w in re.findall(r"process +([0-9.]+) s",
                                          run.stdout)]
    true = {r["run"]: float(r["error:" + QOI]) for r in full}
    if run.returncode != 0:
        return "| %g | %d | %.1f s | none: %s | | | | %s |" % (
            target, len(walls), sum(walls), run.stderr.strip()[:60] + "...",
            cheapest(full, target))
    made = rows(os.path.join(output, "target.csv"))
    chosen = next(r for r in made if r["chosen"] == "1")
    return "| %g | %d | %.1f s | %s | %.2f s | %.2g | %.2g | %s |" % (
        target, len(made), sum(walls), chosen["run"],
        float(chosen["process_wall"]), float(chosen["estimate:" + QOI]),
        true[chosen["run"]], cheapest(full, target))


def main():
    global QOI, LADDER
    liftoff, folder = os.path.abspath(sys.argv[1]), os.path.abspath(
        sys.argv[2])
    rest = sys.argv[3:]
    if rest[:1] == ["--scene"]:
        QOI, LADDER = SCENES[rest[1]]
        rest = rest[2:]
    targets = [float(t) for t in rest] or [1e-2, 3e-3, 1e-3]
    full_run = study(liftoff, os.path.join(folder, "full"), "--no-plot")
    if full_run.returncode != 0:
        sys.exit(full_run.stderr)
    full = rows(os.path.join(folder, "full", "study.csv"))
    print("full ladder: %d runs, process wall %.1f s" % (
        len(full), sum(float(r["process_wall"]) for r in full)))
    print("| target | runs made | their process wall | chosen run | its "
          "process wall | estimated error | true error | full ladder's "
          "cheapest meeting it |\n|---|---|---|---|---|---|---|---|")
    for target in targets:
        print(climb_row(liftoff, folder, target, full), flush=True)


if __name__ == "__main__":
    main()
