#!/usr/bin/env python3
"""Run liftoff's benchmark scenes, each in its own process, and tabulate.

Builds liftoff (Release) in build-bench/, runs the chosen scenes from
benchmarks/scenes/, prints one row per run and appends the rows to
benchmarks/results.csv (with the commit, the label and the date), then
rewrites benchmarks/results.md from the whole CSV.

    benchmarks/run.py --label after S-gamma1 S-gamma1000
    benchmarks/run.py --label mpi --ranks 2 M-gamma1
    benchmarks/run.py --label probe --set "Time integration/End time=0.005" M-gamma1

Wall times come from liftoff's summary.txt (TimerOutput sections); the peak
memory is the largest VmHWM of any rank as liftoff reports it, or, for
programs that do not report it, GNU time's maximum resident set size.
"""

import argparse
import csv
import datetime
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from liftoff_runs import parse_summary, scene_with_overrides  # noqa: E402
BUILD = os.path.join(ROOT, "build-bench")
RESULTS_CSV = os.path.join(HERE, "results.csv")
RESULTS_MD = os.path.join(HERE, "results.md")
EXECUTABLE = os.path.join(BUILD, "liftoff")
COMMIT = None

# Table columns: (key, heading). Times are in seconds.
COLUMNS = [
    ("date", "date"),
    ("commit", "commit"),
    ("label", "label"),
    ("scene", "scene"),
    ("overrides", "overrides"),
    ("ranks", "ranks"),
    ("dofs", "dofs"),
    ("steps", "steps"),
    ("iter_mean", "it/step"),
    ("iter_max", "it max"),
    ("factorisations", "factor."),
    ("wall", "wall"),
    ("setup", "setup+asm"),
    ("foundation", "K_f update"),
    ("factorisation", "factor./prec."),
    ("solve", "solve"),
    ("contact", "contact"),
    ("output", "output"),
    ("rest", "rest"),
    ("per_step", "per step"),
    ("per_iteration", "per it."),
    ("substitution", "subst."),
    ("ratio", "it./subst."),
    ("per_iteration_steady", "per it. w/o factor."),
    ("ratio_steady", "w/o factor./subst."),
    ("memory_mb", "peak MB/rank"),
    ("factor", "factor"),
    ("rhs", "rhs"),
    ("checkpoint", "checkpoint"),
    ("untimed", "untimed"),
    ("subst_per_step", "subst./step"),
    ("floor", "floor"),
    ("ratio_floor", "per step/floor"),
    ("updated_columns", "updated columns"),
    ("probe_difference", "probes vs ref."),
    ("contact_difference", "contact vs ref."),
]


def sh(command, **kwargs):
    print("+ " + " ".join(command), flush=True)
    subprocess.run(command, check=True, **kwargs)


def build():
    sh(["cmake", "-S", ROOT, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release"],
       stdout=subprocess.DEVNULL)
    sh(["cmake", "--build", BUILD, "-j2", "--target", "liftoff"],
       stdout=subprocess.DEVNULL)


def commit():
    if COMMIT:
        return COMMIT
    try:
        out = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short",
                              "HEAD"], capture_output=True, text=True,
                             check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain",
                                "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
        return out + ("+" if dirty else "")
    except (subprocess.CalledProcessError, FileNotFoundError):
        return "unknown"


def scene_file(scene):
    """benchmarks/scenes/<scene>.prm, or a path to any scene (the paper's
    examples in prm/)."""
    if scene.endswith(".prm"):
        return scene
    return os.path.join(HERE, "scenes", scene + ".prm")


def scene_name(scene):
    return os.path.splitext(os.path.basename(scene))[0]


def scene_text(scene, overrides, directory):
    return scene_with_overrides(scene_file(scene), overrides, directory)


def run_one(scene, overrides, ranks, label):
    stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S")
    directory = os.path.join(HERE, "runs", "%s-%s-np%d-%s" %
                             (label, scene_name(scene), ranks, stamp))
    os.makedirs(directory)
    prm = os.path.join(directory, "scene.prm")
    with open(prm, "w") as f:
        f.write(scene_text(scene, overrides, directory))
    command = [EXECUTABLE, prm]
    if ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe",
                   "-np", str(ranks)] + command
    time_file = os.path.join(directory, "time.txt")
    with open(os.path.join(directory, "log.txt"), "w") as log:
        sh(["/usr/bin/time", "-f", "%e %M", "-o", time_file] + command,
           stdout=log, stderr=subprocess.STDOUT)
    return tabulate(directory, scene, overrides, ranks, label)


def tabulate(directory, scene, overrides, ranks, label):
    """One table row from a run's folder."""
    time_file = os.path.join(directory, "time.txt")
    with open(time_file) as f:
        rss_kb = float(f.read().split()[-1])
    values, sections = parse_summary(os.path.join(directory, "summary.txt"))

    def section(*names):
        return sum(sections.get(n, 0.0) for n in names)

    steps = int(values["steps"])
    iter_mean = float(values["active-set iterations per step, mean"])
    wall = float(values["wall time [s]"])
    setup = section("setup", "assembly", "initial acceleration")
    foundation = section("foundation assembly", "foundation update",
                         "factor update")
    factorisation = section("factorisation", "preconditioner")
    solve = section("solve")
    contact = section("contact update")
    output = section("output")
    rhs = section("right hand side")
    checkpoint = section("checkpoint")
    loop = foundation + factorisation + solve + contact
    iterations = iter_mean * steps
    substitution = float(values.get("time per substitution [s]", "0"))
    memory_mb = float(values.get("peak memory per rank, max [MB]",
                                 rss_kb / 1024.0))
    row = {
        "date": datetime.date.today().isoformat(),
        "commit": commit(),
        "label": label,
        "scene": scene_name(scene),
        "overrides": "; ".join(overrides),
        "ranks": ranks,
        "dofs": int(values["dofs"]),
        "steps": steps,
        "iter_mean": "%.2f" % iter_mean,
        "iter_max": values["active-set iterations per step, max"],
        "factorisations": values["factorisations"],
        "wall": "%.2f" % wall,
        "setup": "%.2f" % setup,
        "foundation": "%.2f" % foundation,
        "factorisation": "%.2f" % factorisation,
        "solve": "%.2f" % solve,
        "contact": "%.3f" % contact,
        "output": "%.3f" % output,
        "rest": "%.2f" % (wall - setup - loop - output),
        "per_step": "%.4g" % ((wall - setup) / max(steps, 1)),
        "per_iteration": "%.4g" % (loop / max(iterations, 1)),
        "substitution": "%.4g" % substitution if substitution > 0 else "",
        "ratio": ("%.2f" % (loop / max(iterations, 1) / substitution)
                  if substitution > 0 else ""),
        "memory_mb": "%.0f" % memory_mb,
        # Older binaries do not name their factor: MUMPS's LU then.
        "factor": values.get("factor", "MUMPS LU"),
        "rhs": "%.3f" % rhs,
        "checkpoint": "%.3f" % checkpoint,
        "untimed": "%.2f" % (wall - sum(sections.values())),
        "subst_per_step": "%.2f" % (float(values.get("substitutions", "0"))
                                    / max(steps, 1)),
        "updated_columns": values.get("factor updates, columns", ""),
        "directory": directory,
    }
    return row


def read_history(directory):
    with open(os.path.join(directory, "history.csv")) as f:
        return list(csv.DictReader(f))


def compare_histories(rows, reference):
    """Each row's probe histories against those of the reference run: the
    largest difference over the steps relative to the largest |value| of
    the reference's probe; and the largest difference of the contact
    fractions."""
    ref = read_history(reference["directory"])
    probes = [k for k in ref[0] if k.startswith("w(")]
    for row in rows:
        own = read_history(row["directory"])
        if len(own) != len(ref):
            row["probe_difference"] = "%d vs %d rows" % (len(own), len(ref))
            continue
        worst = 0.0
        for k in probes:
            scale = max(abs(float(r[k])) for r in ref) or 1.0
            worst = max(worst, max(abs(float(a[k]) - float(b[k]))
                                   for a, b in zip(own, ref)) / scale)
        row["probe_difference"] = "%.2g" % worst
        row["contact_difference"] = "%.2g" % max(
            abs(float(a["contact_fraction"]) - float(b["contact_fraction"]))
            for a, b in zip(own, ref))


def set_floor(rows, floor):
    """The floor of a scene: one substitution with the best symmetric factor
    (CHOLMOD's), measured in the same run; each row's time per step against
    it."""
    for row in rows:
        row["floor"] = "%.4g" % floor
        row["ratio_floor"] = "%.1f" % (float(row["per_step"]) / floor)


def derived(row):
    """Columns computed from the others (also for rows of older CSVs): the
    time in the active-set loop per iteration without factorisations, and
    its ratio to a substitution."""
    iterations = float(row["iter_mean"]) * int(row["steps"])
    steady = sum(float(row[k]) for k in ("foundation", "solve", "contact"))
    row["per_iteration_steady"] = "%.4g" % (steady / max(iterations, 1))
    if row.get("substitution") and float(row["substitution"]) > 0:
        row["ratio_steady"] = "%.2f" % (steady / max(iterations, 1)
                                        / float(row["substitution"]))
    else:
        row["ratio_steady"] = ""
    return row


def write_tables(new_rows):
    rows = []
    if os.path.exists(RESULTS_CSV):
        with open(RESULTS_CSV) as f:
            rows = list(csv.DictReader(f))
    rows = [derived(r) for r in rows + new_rows]
    with open(RESULTS_CSV, "w", newline="") as f:
        # "\n": the csv module's default "\r\n" would rewrite every line
        # of the committed file at each run.
        writer = csv.DictWriter(f, fieldnames=[k for k, _ in COLUMNS],
                                extrasaction="ignore", lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    lines = ["# Benchmark results",
             "",
             "Written by `benchmarks/run.py` from `results.csv`; times in "
             "seconds. `per step` excludes set-up; `per it.` is the time in "
             "the active-set loop (K_f update, factorisation, solve, contact "
             "update) per iteration, `per it. w/o factor.` the same without "
             "the factorisations; `subst.` is one forward and back "
             "substitution with the stored factor, measured in the same run.",
             "",
             "| " + " | ".join(h for _, h in COLUMNS) + " |",
             "|" + "---|" * len(COLUMNS)]
    for r in rows:
        lines.append("| " + " | ".join(str(r.get(k, "")) for k, _ in COLUMNS)
                     + " |")
    with open(RESULTS_MD, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("scenes", nargs="+",
                        help="names of files in benchmarks/scenes/ without "
                        ".prm (S-gamma1, S-gamma1000, M-gamma1, ...)")
    parser.add_argument("--label", required=True,
                        help="what this run measures, e.g. baseline")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--set", action="append", default=[],
                        metavar="Section/Entry=value",
                        help="override a parameter (repeatable)")
    parser.add_argument("--no-build", action="store_true")
    parser.add_argument("--executable",
                        help="run this liftoff instead of building one "
                        "(e.g. an older commit's, for a baseline)")
    parser.add_argument("--commit", help="commit to record with "
                        "--executable")
    parser.add_argument("--baseline", metavar="EXECUTABLE", action="append",
                        default=[],
                        help="run each scene with this binary first, then "
                        "with the built one, back to back (label "
                        "LABEL-baseline, or LABEL-baseline-COMMIT when "
                        "repeated); the first is the reference of the "
                        "history comparison")
    parser.add_argument("--baseline-commit", action="append", default=[])
    parser.add_argument("--repeat", type=int, default=1,
                        help="run everything this many times, interleaved "
                        "(baselines and new binary of a scene back to back); "
                        "prints the spread of the time per step")
    parser.add_argument("--tabulate", metavar="RUN_FOLDER",
                        help="do not run: tabulate this finished run of the "
                        "one scene given (with its --label, --ranks, --set)")
    args = parser.parse_args()
    global EXECUTABLE, COMMIT
    if args.executable:
        EXECUTABLE = os.path.abspath(args.executable)
        COMMIT = args.commit or "unknown"
        args.no_build = True
    for override in args.set:
        if not re.match(r"^[^=/]+(/[^=/]+)+=.*$", override):
            parser.error("--set wants Section/Entry=value, got " + override)
    for scene in args.scenes:
        if not os.path.exists(scene_file(scene)):
            parser.error("no scene " + scene_file(scene))
    if args.tabulate:
        row = derived(tabulate(args.tabulate, args.scenes[0], args.set,
                               args.ranks, args.label))
        write_tables([row])
        return 0
    if not args.no_build:
        build()
    commits = args.baseline_commit + ["unknown"] * len(args.baseline)
    baselines = list(zip(args.baseline, commits))
    rows = []
    for _ in range(args.repeat):
        for scene in args.scenes:
            scene_rows = []
            for executable, baseline_commit in baselines:
                EXECUTABLE, built = os.path.abspath(executable), EXECUTABLE
                COMMIT, own = baseline_commit, COMMIT
                label = args.label + "-baseline" + (
                    "-" + baseline_commit if len(baselines) > 1 else "")
                scene_rows.append(derived(run_one(scene, args.set,
                                                  args.ranks, label)))
                EXECUTABLE, COMMIT = built, own
            scene_rows.append(derived(run_one(scene, args.set, args.ranks,
                                              args.label)))
            own = scene_rows[-1]
            if "CHOLMOD" in own["factor"] and float(own["substitution"] or 0):
                set_floor(scene_rows, float(own["substitution"]))
            compare_histories(scene_rows, scene_rows[0])
            for row in scene_rows:
                print("  ".join("%s=%s" % (h, row.get(k, ""))
                                for k, h in COLUMNS[3:]), flush=True)
            rows += scene_rows
    if args.repeat > 1:
        print("time per step over %d repetitions (min, median, max):"
              % args.repeat)
        for key in sorted({(r["scene"], r["label"]) for r in rows}):
            times = sorted(float(r["per_step"]) for r in rows
                           if (r["scene"], r["label"]) == key)
            print("  %s %s: %.4g, %.4g, %.4g (spread %.0f %%)" % (
                key + (times[0], times[len(times) // 2], times[-1],
                       100 * (times[-1] / times[0] - 1))))
    write_tables(rows)
    print("appended %d row(s) to %s; table in %s" %
          (len(rows), RESULTS_CSV, RESULTS_MD))


if __name__ == "__main__":
    sys.exit(main())
