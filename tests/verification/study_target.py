#!/usr/bin/env python3
"""scripts/liftoff-study --target against closed forms.

    study_target.py LIFTOFF LIFTOFF_STUDY

Two scenes whose converged value is known exactly:

- The rigid bounce: a free plate (quarter, Q1) on a bilateral bed,
  Gamma = 100, under a uniform pressure q = 1 applied at tau = 0. The plate
  translates rigidly (the bed and the inertia are both consistent with the
  uniform load, so every mesh holds the motion exactly), w_tt + Gamma w = q:
  w = (q / Gamma) (1 - cos(10 tau)), up to tau = 0.7. Ladder: time steps
  0.02 ... 2.5e-3 x 2 and 4 cells per side; only the time step errs. Again
  with automatic steps (Time step control = error), the Error tolerance
  laddered from 1e-2 by factors of 8 (--tolerances).
- A clamped disc (radius 1/2, Delta = 0.05, nu = 0.3) under q = 1, static,
  Q2, 0 to 2 global refinements: w(0) = q a^4 / 64 + q a^2 / (4 S) (as
  circular_plate.py). Only the mesh errs.

For each, the climb to its target (1e-3 and 1e-4, relative) must choose a
run whose true error (the largest difference from the closed form over
the run's own history rows, relative to the closed form's largest
magnitude) is below the target, with an estimate within a factor 2 of it,
and, for fixed steps, whose unknowns x steps are at most 4 times those of
the cheapest run of the full ladder that meets the target by its true
error (4: one mesh rung in 2D; measured 2.8 for the bounce, where the
climb must try the second mesh to learn that it changes nothing, and 1
for the disc). The full ladder is then run by the study tool into the
same folder with --reuse (the climb's runs are kept).

Hostile input: a target <= 0, NaN, infinite or not a number, a bad assumed
order, --target with --sweep zip, --time-steps or --target without
--tolerances on a scene with automatic steps (from --set, the scene or a
file it includes),
--tolerances on fixed steps or without --target, rungs of --tolerances
whose steps the largest step or the finest level sets instead, a ladder
of one run, --absolute without --target, an unknown quantity, a ladder
that runs out before the target (the best estimate named), a run that
fails: each one line on stderr, a non-zero exit, and no target.md or
target.csv written.
"""

import csv
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import pressed_plate, pressure, scene_text  # noqa: E402

BOUNCE = scene_text(
    {"Plate": {"Thickness ratio": 0.1},
     "Foundation": {"Model": "bilateral", "Stiffness": 100},
     "Discretization": {"Symmetry": "quarter", "Polynomial degree": 1},
     "Time integration": {"End time": 0.7},
     "Output": {"Probe points": "0.25, 0", "Write energies": "false"}},
    pressure(1))
BOUNCE_LADDER = ["--time-steps", "0.02,0.01,5e-3,2.5e-3",
                 "--refine", "Discretization/Cells along x=2,4",
                 "--refine", "Discretization/Cells along y=2,4",
                 "--qoi", "w(0.25;0)"]

A, NU, CHI, DELTA = 0.5, 0.3, 5.0 / 6.0, 0.05
S = 6 * CHI * (1 - NU) / DELTA**2
DISC = scene_text(pressed_plate(DELTA, NU, 1),
                  {"Discretization": {"Shape": "disc", "Radius": A},
                   "Boundary conditions": {"Outer": "clamped"},
                   "Output": {"Probe points": "0, 0"}})
DISC_LADDER = ["--refine", "Discretization/Global refinements=0,1,2",
               "--qoi", "w(0;0)"]
# The bounce with automatic steps: Error tolerance laddered by factors of 8
# (which halve the steps), rows every 0.1, so that the tolerance, not the
# largest step, sets the steps from the first rung on.
AUTOMATIC = ["--set", "Time integration/Time step control=error",
             "--set", "Time integration/Time step=0.1",
             "--set", "Time integration/Finest step level=12"]
AUTOMATIC_LADDER = AUTOMATIC + [
    "--tolerances", "1e-2,1.25e-3,1.5625e-4,1.953125e-5,2.44140625e-6"
] + BOUNCE_LADDER[2:]


def bounce_exact(tau):
    return 0.01 * (1 - math.cos(10 * tau))


def disc_exact(tau):
    return A**4 / 64 + A**2 / (4 * S)


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def true_error(folder, label, column, exact, magnitude):
    rows = read_rows(os.path.join(folder, "runs", label, "history.csv"))
    return max(abs(float(r[column]) - exact(float(r["tau"])))
               for r in rows) / magnitude


def study(tool, liftoff, scene, output, *extra):
    return subprocess.run([tool, scene, "--executable", liftoff,
                           "--no-plot", "--output", output] + list(extra),
                          capture_output=True, text=True)


def climb_and_ladder(tool, liftoff, work, case):
    """The climb to the target, then the full ladder; the checks."""
    name, scene, ladder, target, column, exact, magnitude = case
    output = os.path.join(work, name)
    run = study(tool, liftoff, scene, output, "--target", str(target),
                *ladder)
    print(run.stdout)
    check(run.returncode == 0, "%s: the climb to %g runs (exit %d: %s)"
          % (name, target, run.returncode, run.stderr.strip()))
    if run.returncode:
        return
    made = read_rows(os.path.join(output, "target.csv"))
    chosen = next(r for r in made if r["chosen"] == "1")
    check(all(any(line.startswith("[%d] %s " % (k, r["run"]))
                  for line in run.stdout.splitlines())
              for k, r in enumerate(made, 1)),
          "%s: a progress line for each of the %d runs made"
          % (name, len(made)))
    error = true_error(output, chosen["run"], column, exact, magnitude)
    estimate = float(chosen["estimate:" + column])
    check(error <= target, "%s: the chosen run %s has true error %.3g <= "
          "target %g" % (name, chosen["run"], error, target))
    check(0.5 <= estimate / error <= 2, "%s: its estimate %.3g within a "
          "factor 2 of the true error %.3g" % (name, estimate, error))
    if "--tolerances" in ladder:
        # A full study does not ladder tolerances.
        return

    full = study(tool, liftoff, scene, output, "--reuse", "--jobs", "2",
                 *ladder)
    check(full.returncode == 0, "%s: the full ladder runs (exit %d: %s)"
          % (name, full.returncode, full.stderr.strip()))
    if full.returncode:
        return
    rows = read_rows(os.path.join(output, "study.csv"))
    work_of = {r["run"]: int(r["dofs"]) * max(1, int(r["steps"]))
               for r in rows}
    meeting = [r["run"] for r in rows
               if true_error(output, r["run"], column, exact,
                             magnitude) <= target]
    cheapest = min(meeting, key=work_of.get)
    factor = work_of[chosen["run"]] / work_of[cheapest]
    print("%s: chosen %s (dofs x steps %d, %d runs made), the full ladder's "
          "cheapest meeting %g by its true error %s (%d): factor %.2f"
          % (name, chosen["run"], work_of[chosen["run"]], len(made), target,
             cheapest, work_of[cheapest], factor))
    check(factor <= 4, "%s: the chosen run's unknowns x steps %.2f times "
          "the cheapest meeting the target in the full ladder (<= 4)"
          % (name, factor))


def refused(tool, liftoff, scene, output, what, expect, *extra):
    """A study that must stop with one line, non-zero, no target files."""
    run = study(tool, liftoff, scene, output, *extra)
    message = run.stderr.strip()
    left = [n for n in ("target.md", "target.csv", "target.tmp.md",
                        "target.tmp.csv")
            if os.path.exists(os.path.join(output, n))]
    check(run.returncode != 0 and expect in message and "\n" not in message
          and not left,
          "%s: exit %d, one line: %s%s" % (what, run.returncode, message,
                                           "; left %s" % left if left
                                           else ""))


def hostile(tool, liftoff, work, scene):
    fresh = os.path.join(work, "never")
    for value in ("0", "-1e-3", "nan", "inf", "abc"):
        refused(tool, liftoff, scene, fresh, "--target %s" % value,
                "--target wants a number > 0, got '%s'" % value,
                "--target=" + value, *BOUNCE_LADDER)
    refused(tool, liftoff, scene, fresh, "--assumed-order 0",
            "--assumed-order wants a number > 0", "--target", "1e-3",
            "--assumed-order", "0", *BOUNCE_LADDER)
    refused(tool, liftoff, scene, fresh, "--sweep zip", "--target climbs a "
            "product ladder", "--target", "1e-3", "--sweep", "zip",
            "--time-steps", "0.02,0.01")
    refused(tool, liftoff, scene, fresh, "a ladder of one run",
            "--target needs a ladder", "--target", "1e-3", "--time-steps",
            "0.02")
    refused(tool, liftoff, scene, fresh, "--absolute alone",
            "--absolute applies to --target", "--absolute",
            *BOUNCE_LADDER)
    # Automatic steps: Time step is then the row interval, not the step.
    refused(tool, liftoff, scene, fresh, "--target in Time step with "
            "automatic steps", "--time-steps with Time integration/Time "
            "step control = error: Time step is then only the row interval",
            "--target", "1e-2", "--set",
            "Time integration/Time step control=error", *BOUNCE_LADDER)
    refused(tool, liftoff, scene, fresh, "a full study in Time step with "
            "automatic steps", "--time-steps with Time integration/Time "
            "step control = error", "--set",
            "Time integration/Time step control = error", *BOUNCE_LADDER)
    automatic = os.path.join(work, "automatic.prm")
    with open(automatic, "w") as f:
        f.write(BOUNCE + "subsection Time integration\n  set Time step "
                "control = error\nend\n")
    refused(tool, liftoff, automatic, fresh, "--target on a mesh ladder of "
            "a scene with automatic steps", "--target with Time "
            "integration/Time step control = error needs --tolerances",
            "--target", "1e-2", *BOUNCE_LADDER[2:])
    # Automatic steps set in an included file: seen in the first run's
    # used parameters, before a second run.
    included = os.path.join(work, "included.prm")
    with open(included, "w") as f:
        f.write("include %s\n" % automatic)
    refused(tool, liftoff, included, os.path.join(work, "included"),
            "--target on a scene that includes automatic steps", "--time-"
            "steps with Time integration/Time step control = error",
            "--target", "1e-2", *BOUNCE_LADDER)
    refused(tool, liftoff, scene, fresh, "--tolerances on fixed steps",
            "--tolerances ladders Time integration/Error tolerance in a "
            "climb to --target, on a scene with Time integration/Time step "
            "control = error; this one's steps are fixed", "--target",
            "1e-2", "--tolerances", "1e-2,1e-3")
    refused(tool, liftoff, automatic, fresh, "--tolerances without "
            "--target", "--tolerances ladders", "--tolerances", "1e-2,1e-3")
    check(not os.path.exists(fresh), "no folder made for a refused option")
    # On the bounce's folder, whose runs --reuse takes.
    bounce = os.path.join(work, "bounce")
    refused(tool, liftoff, scene, bounce, "an unknown quantity",
            "'w(9;9)' is not a column of history.csv", "--reuse",
            "--target", "1e-3", "--time-steps", "0.02,0.01",
            "--qoi", "w(9;9)")
    refused(tool, liftoff, scene, bounce, "a ladder too short",
            "the ladder ran out before the target 1e-07: the best estimate "
            "was ", "--reuse", "--target", "1e-7", *BOUNCE_LADDER)
    # Rungs whose steps the tolerance does not set.
    refused(tool, liftoff, scene, os.path.join(work, "capped"),
            "tolerances under the largest step", "run c2-tol0.01: 35 steps "
            "over 35 intervals of Time step = 0.02: the largest step, not "
            "the tolerance, sets most of them", "--target", "1e-3",
            *(AUTOMATIC_LADDER + ["--set",
                                  "Time integration/Time step=0.02"]))
    refused(tool, liftoff, scene, os.path.join(work, "floor"),
            "tolerances below the finest level", "steps stayed above its "
            "Time integration/Error tolerance = 1e-06; raise Time "
            "integration/Finest step level (3, steps of 0.0125)",
            "--target", "1e-3", *(AUTOMATIC + [
                "--set", "Time integration/Finest step level=3",
                "--tolerances", "1e-6,1e-9"] + BOUNCE_LADDER[2:]))
    refused(tool, liftoff, scene, os.path.join(work, "failing"),
            "a run that fails", "run c2-dt0.02 failed (exit",
            "--target", "1e-3", "--set", "Plate/Thickness ratio=-1",
            *BOUNCE_LADDER)


def main():
    liftoff, tool = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        scenes = {}
        for name, text in (("bounce", BOUNCE), ("disc", DISC)):
            scenes[name] = os.path.join(work, name + ".prm")
            with open(scenes[name], "w") as f:
                f.write(text)
        for case in (("bounce", scenes["bounce"], BOUNCE_LADDER, 1e-3,
                      "w(0.25;0)", bounce_exact, 0.02),
                     ("automatic", scenes["bounce"], AUTOMATIC_LADDER, 1e-3,
                      "w(0.25;0)", bounce_exact, 0.02),
                     ("disc", scenes["disc"], DISC_LADDER, 1e-4, "w(0;0)",
                      disc_exact, disc_exact(0))):
            climb_and_ladder(tool, liftoff, work, case)
        hostile(tool, liftoff, work, scenes["bounce"])
    finish()


if __name__ == "__main__":
    main()
