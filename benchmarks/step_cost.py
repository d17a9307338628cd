#!/usr/bin/python3
"""What a time step costs in substitutions, and what the design outputs add.

    benchmarks/step_cost.py [--executable NEW] [--baseline OLD] [--repeat 3]
                            [SCENE ...]       (default: S-gamma1 M-gamma1)

Runs each scene of benchmarks/scenes/ twice per repetition: as it is, and
with `Output/Write moment extremes` and `Output/Write envelopes` on; with
--baseline the two binaries alternate, run by run, so that both see the
same load. Per run, from its summary.txt:

- step: the run's wall time less its set-up sections (setup, assembly,
  initial acceleration), per step;
- subst.: one forward and back substitution with the stored factor,
  timed in the same run (the floor: a step needs at least one);
- step / subst.: the ratio, which holds on any machine;
- output / subst.: the `output` section per step in substitutions (the
  history row, probes and, in the second run, the moment extremes and
  envelopes);
- design / subst.: the second run's output section less the first run's,
  per step in substitutions: what the moment extremes and envelopes cost;
- process: the whole process's wall time (start-up included).

Prints the median of --repeat repetitions of each figure. A run's files
stay in benchmarks/runs/step-cost-* (not committed).
"""

import argparse
import datetime
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from liftoff_runs import (parse_summary, run_scene_timed,  # noqa: E402
                          scene_with_overrides)

DESIGN_OUTPUTS = ["Output/Write moment extremes=true",
                  "Output/Write envelopes=true"]
SETUP_SECTIONS = ("setup", "assembly", "initial acceleration")


def one_run(executable, scene, overrides, folder):
    """The figures of one run of `scene` with `overrides`."""
    text = scene_with_overrides(os.path.join(HERE, "scenes", scene + ".prm"),
                                overrides, folder)
    code, process_wall, _ = run_scene_timed(executable, text, folder)
    if code != 0:
        raise RuntimeError("liftoff failed (exit %d) in %s" % (code, folder))
    values, sections = parse_summary(os.path.join(folder, "summary.txt"))
    steps = max(int(values["steps"]), 1)
    setup = sum(sections.get(name, 0.0) for name in SETUP_SECTIONS)
    return {"step": (float(values["wall time [s]"]) - setup) / steps,
            "substitution": float(values["time per substitution [s]"]),
            "output": sections.get("output", 0.0) / steps,
            "process": process_wall}


def measure(executable, scene, label, repeat_index, stamp):
    """The scene as it is and with the design outputs, one after the other;
    the figures of both in substitutions."""
    base = os.path.join(HERE, "runs", "step-cost-%s-%s-%s-%d"
                        % (stamp, label, scene, repeat_index))
    plain = one_run(executable, scene, [], base + "-plain")
    design = one_run(executable, scene, DESIGN_OUTPUTS, base + "-design")
    floor = plain["substitution"]
    return {"step ms": 1e3 * plain["step"],
            "subst. ms": 1e3 * floor,
            "step / subst.": plain["step"] / floor,
            "output / subst.": plain["output"] / floor,
            "design / subst.": (design["output"] - plain["output"])
            / design["substitution"],
            "process s": plain["process"]}


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("scenes", nargs="*",
                        default=["S-gamma1", "M-gamma1"])
    parser.add_argument("--executable",
                        default=os.path.join(ROOT, "build", "liftoff"))
    parser.add_argument("--baseline", help="an older liftoff, run in "
                        "alternation with --executable")
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()

    binaries = [("new", os.path.abspath(args.executable))]
    if args.baseline:
        binaries.insert(0, ("baseline", os.path.abspath(args.baseline)))
    for _, executable in binaries:
        if not os.access(executable, os.X_OK):
            parser.error("no executable liftoff at " + executable)
    for scene in args.scenes:
        if not os.path.isfile(os.path.join(HERE, "scenes", scene + ".prm")):
            parser.error("no scene %s in benchmarks/scenes/" % scene)
    if args.repeat < 1:
        parser.error("--repeat wants at least 1")
    stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S")
    columns = ["step ms", "subst. ms", "step / subst.", "output / subst.",
               "design / subst.", "process s"]
    print("| scene | binary | " + " | ".join(columns) + " |")
    print("|---|---|" + "---|" * len(columns))
    for scene in args.scenes:
        runs = {label: [] for label, _ in binaries}
        for k in range(args.repeat):
            for label, executable in binaries:
                runs[label].append(measure(executable, scene, label, k,
                                           stamp))
        for label, _ in binaries:
            medians = [statistics.median(r[c] for r in runs[label])
                       for c in columns]
            print("| %s | %s | " % (scene, label)
                  + " | ".join("%.3g" % m for m in medians) + " |",
                  flush=True)


if __name__ == "__main__":
    main()
