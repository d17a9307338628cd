"""Runs of one scene made side by side and their results published
together: what scripts/liftoff-study and scripts/liftoff-damage share.

A tool builds its runs (dicts with "label", "scene" (the text), "work": a
relative cost), then execute() makes each in args.output/runs/LABEL (or
with args.reuse keeps one that holds the same scene and a completed
summary), --jobs of them at a time in liftoff workers (liftoff_workers.py:
one process each, start-up paid once), printing the plan and "k of N" with
the time left; a failed run is named when the others are done. The tool's
own files are written under temporary names and published together
(write_files), so that an interrupted tool leaves the earlier files or all
of the new ones. A folder
holds one tool's results: claim() refuses an earlier one unless --reuse or
--overwrite.
"""

import concurrent.futures
import os
import shutil
import signal
import threading
import time

import numpy as np

from liftoff_qoi import StudyError
from liftoff_runs import parse_summary, read_table, used_parameters
from liftoff_workers import Workers

TIME_STEP = "Time integration/Time step"
# Kept in each run's folder: its wall and CPU seconds as a process of its
# own, and the scene's wall seconds in its worker and the worker's
# start-up, which the run's own summary.txt cannot know.
TIMING = "study_timing.txt"
# Guards the creation of a tool's pool of workers (args.workers).
WORKERS_LOCK = threading.Lock()


def run_directory(run, args):
    return os.path.join(args.output, "runs", run["label"])


def is_reusable(run, args):
    """With --reuse: whether the run's folder holds the same scene, a
    completed summary and the process's times (the run's cost; a run made
    before the tool kept them is made again)."""
    directory = run_directory(run, args)
    summary = os.path.join(directory, "summary.txt")
    if not args.reuse or not all(
            os.path.exists(os.path.join(directory, name))
            for name in ("summary.txt", TIMING)):
        return False
    try:
        with open(os.path.join(directory, "scene.prm")) as f:
            return (f.read() == run["scene"]
                    and parse_summary(summary)[0].get("status")
                    == "completed")
    except OSError:
        return False


def make(run, args):
    """Run the scene in one of the tool's liftoff workers (a thread may
    call this while others run) and keep its times with it: the scene's
    wall and CPU seconds in the worker, and the start-up that the worker's
    process paid once, which a run alone would pay too."""
    directory = run_directory(run, args)
    with WORKERS_LOCK:
        if getattr(args, "workers", None) is None:
            args.workers = Workers(args.executable, args.ranks)
    cost = args.workers.run(run["scene"], directory)
    if cost.code != 0 and failed_to_start(directory):
        # Open MPI's start-up, not the run, failed (seen 2 times in 435
        # runs on the shared 2-core machine at load 6): once more.
        cost = args.workers.run(run["scene"], directory)
    if cost.code in (128 + signal.SIGINT, 128 + signal.SIGTERM):
        # The run was stopped as the tool was (Ctrl-C reaches the whole
        # process group): the tool's interruption, not the run's failure,
        # whichever of the two the tool notices first.
        raise KeyboardInterrupt
    if cost.code != 0:
        raise StudyError("run %s failed (exit %d)%s; see %s"
                         % (run["label"], cost.code, reason(directory),
                            os.path.join(directory, "log.txt")))
    write_atomic(os.path.join(directory, TIMING),
                 "process: %r\ncpu: %r\nscene: %r\nstart-up: %r\n"
                 % (cost.process_wall(), cost.process_cpu(), cost.wall,
                    cost.start_up_wall))


def reason(directory):
    """liftoff's own message on the scene, from a failed run's log (the
    lines after "liftoff: error in SCENE:"), as ": message", or ""."""
    try:
        with open(os.path.join(directory, "log.txt"), errors="replace") as f:
            lines = f.read().splitlines()
    except OSError:
        return ""
    for k, line in enumerate(lines):
        if line.startswith("liftoff: error in "):
            message = " ".join(v.strip() for v in lines[k + 1:k + 3])
            return ": " + message[:300] if message else ""
    return ""


def failed_to_start(directory):
    """Whether the run's log shows MPI_Init failing before liftoff read its
    scene."""
    try:
        with open(os.path.join(directory, "log.txt")) as f:
            return "before MPI_INIT completed" in f.read()
    except OSError:
        return False


def load(run, args):
    """Fill in what the run's files say."""
    directory = run_directory(run, args)
    values, _ = parse_summary(os.path.join(directory, "summary.txt"))
    times, _ = parse_summary(os.path.join(directory, TIMING))
    used = used_parameters(directory)
    profiles_file = os.path.join(directory, "profiles.csv")
    run.update({
        "directory": directory,
        "cells": int(values["cells"]),
        "p": int(values["degree"]),
        "dofs": int(values["dofs"]),
        # With automatic steps "steps" counts the rows (multiples of Time
        # step); the steps taken are what the run cost.
        "steps": int(float(values.get("time steps taken",
                                      values["steps"]))),
        "dtau": float(used[TIME_STEP]),
        "run_wall": float(values["wall time [s]"]),
        "process_wall": float(times["process"]),
        "process_cpu": float(times["cpu"]),
        # The scene's own time in its worker (a timing kept before the
        # workers has the process's only).
        "scene_wall": float(times.get("scene", times["process"])),
        "it_mean": float(values["active-set iterations per step, mean"]),
        "it_max": int(values["active-set iterations per step, max"]),
        # With automatic steps only: the steps taken and those that stayed
        # above the tolerance at the finest level.
        "taken": int(float(values.get("time steps taken", "0"))),
        "above": int(float(values.get(
            "time steps above Error tolerance at the finest level", "0"))),
        "history": read_table(os.path.join(directory, "history.csv")),
        "profiles": (read_table(profiles_file)
                     if os.path.exists(profiles_file) else None),
        "used": used,
    })


def duration(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return "%d s" % seconds
    if seconds < 3600:
        return "%d min %02d s" % divmod(seconds, 60)
    return "%d h %02d min" % (seconds // 3600, seconds % 3600 // 60)


class Progress:
    """The plan, and "k of N" with the time so far and an estimate of the
    time left. A run's time in its worker is taken as a + b * work: a what
    lies outside the wall time the run reports (reading the scene, writing
    the results; the worker's start-up is paid once, not per run), b * work
    the run itself, with b the reported wall time of the runs made so far
    over their work (dofs times steps up to a factor; the large runs weigh
    most). The sum over the runs not yet made is divided by the runs made
    side by side."""

    def __init__(self, runs, slots, tool):
        self.runs = runs
        self.tool = tool
        self.slots = slots
        self.start = time.perf_counter()
        self.made = []          # (work, time in the worker, run's own wall)
        self.done = 0

    def plan(self, args, axes):
        to_make = [r for r in self.runs if not r["reused"]]
        work = sum(r["work"] for r in to_make)
        largest = max((r["work"] for r in to_make), default=0)
        print("%s: %d runs (%s)%s; %d at a time (--jobs %d, %d "
              "rank%s per run)"
              % (self.tool, len(self.runs), " x ".join(axes) or "the scene alone",
                 ", %d reused" % (len(self.runs) - len(to_make))
                 if len(to_make) < len(self.runs) else "",
                 self.slots, args.jobs, args.ranks,
                 "s" if args.ranks > 1 else ""), flush=True)
        if to_make:
            print("  estimated cost (dofs x steps): %.4g times the first "
                  "run to make, the largest run %.0f %% of it; time "
                  "estimate after the first run"
                  % (work / to_make[0]["work"], 100 * largest / work),
                  flush=True)

    def left(self):
        """Seconds left for the runs not yet made, or None."""
        if not self.made:
            return None
        work, scene, wall = map(np.array, zip(*self.made))
        a = max(0.0, float(np.mean(scene - wall)))
        b = wall.sum() / work.sum()
        pending = [r["work"] for r in self.runs
                   if not r["reused"] and "process_wall" not in r]
        return sum(a + b * w for w in pending) / self.slots

    def report(self, run):
        self.done += 1
        if not run["reused"]:
            self.made.append((run["work"], run["scene_wall"],
                              run["run_wall"]))
        left = self.left()
        print("[%d of %d] %-24s dofs %7d  steps %5d  process %8.3f s%s   "
              "elapsed %s%s"
              % (self.done, len(self.runs), run["label"], run["dofs"],
                 run["steps"], run["process_wall"],
                 "  (reused)" if run["reused"] else "",
                 duration(time.perf_counter() - self.start),
                 "" if left is None or self.done == len(self.runs)
                 else ", about %s left" % duration(left)), flush=True)


def execute(runs, args, check_first, tool="liftoff-study"):
    """Make (or with --reuse find) every run; the first alone, so that
    check_first(run) can refuse a misspelt quantity before the others run,
    then the others side by side: --jobs processes, a run under mpirun
    taking --ranks of them."""
    for run in runs:
        run["reused"] = is_reusable(run, args)
    slots = max(1, args.jobs // args.ranks)
    progress = Progress(runs, slots, tool)
    progress.plan(args, args.axes)

    def finish(run):
        load(run, args)
        progress.report(run)

    first, rest = runs[0], runs[1:]
    if not first["reused"]:
        make(first, args)
    finish(first)
    check_first(first)
    for run in rest:
        if run["reused"]:
            finish(run)
    # The largest runs first: side by side, the small ones then fill the
    # gaps at the end, and the estimate of the time left learns early
    # what the large ones cost.
    pending = sorted((run for run in rest if not run["reused"]),
                     key=lambda run: -run["work"])
    with concurrent.futures.ThreadPoolExecutor(slots) as pool:
        futures = {pool.submit(make, run, args): run for run in pending}
        failures = []
        try:
            for future in concurrent.futures.as_completed(futures):
                try:
                    future.result()
                except StudyError as e:
                    # The other runs go on: each made is kept for --reuse
                    # once the failed one's scene is mended.
                    failures.append(e)
                    continue
                finish(futures[future])
        except BaseException:
            # Interrupted: runs already started finish; none is started.
            for future in futures:
                future.cancel()
            raise
    if failures:
        raise StudyError("%s%s" % (failures[0], "" if len(failures) == 1
                                   else " (and %d other runs failed)"
                                   % (len(failures) - 1)))


def write_atomic(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def temporary(path):
    """Where a study file is written before it is published; the extension
    is kept (matplotlib infers the format from it)."""
    stem, extension = os.path.splitext(path)
    return stem + ".tmp" + extension


def earlier_study(output, files):
    """What an earlier study left in the folder (its files and runs/)."""
    found = [name for name in files
             if os.path.exists(os.path.join(output, name))]
    if os.path.isdir(os.path.join(output, "runs")):
        found.append("runs/")
    return found


def claim(args, files):
    """A folder holds one study, as a run's folder holds one run: an
    earlier study there is continued (--reuse), removed (--overwrite) or
    refused, before anything is changed. Otherwise its tables would be
    replaced silently and its runs would stay as orphans beside the new."""
    earlier = earlier_study(args.output, files)
    if not earlier or args.reuse:
        return
    if not args.overwrite:
        raise StudyError("%s holds an earlier study (%s); continue it with "
                         "--reuse, give another --output, or remove it with "
                         "--overwrite" % (args.output, ", ".join(earlier)))
    remove_study(args.output, files)


def remove_study(output, files):
    """The earlier study's files and run folders (a folder under runs/ with
    the scene.prm the tool writes); anything else stays."""
    for name in files:
        for path in (os.path.join(output, name),
                     temporary(os.path.join(output, name))):
            if os.path.exists(path):
                os.remove(path)
    runs = os.path.join(output, "runs")
    if not os.path.isdir(runs):
        return
    for entry in os.scandir(runs):
        if entry.is_dir() and os.path.exists(os.path.join(entry.path,
                                                          "scene.prm")):
            shutil.rmtree(entry.path)
    if not os.listdir(runs):
        os.rmdir(runs)


def publish(output, files, written):
    """Move the study files, each written under temporary(path), into place
    together, and remove an earlier study's files this one did not write
    (a plot left from a --reuse with other settings). SIGINT and SIGTERM
    are held meanwhile, so that an interrupted study leaves the earlier
    files or all of the new ones, never a mixture."""
    held = signal.pthread_sigmask(signal.SIG_BLOCK,
                                  {signal.SIGINT, signal.SIGTERM})
    try:
        for name in files:
            path = os.path.join(output, name)
            if name in written:
                os.replace(temporary(path), path)
            elif os.path.exists(path):
                os.remove(path)
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)


def write_files(args, files, tables, plots=()):
    """The tables and the plots (name, draw(path)), each written under its
    temporary name first, then published together; an interruption leaves
    no temporary file."""
    path = {name: os.path.join(args.output, name) for name in files}
    written = []
    try:
        for name, text in tables.items():
            written.append(name)
            with open(temporary(path[name]), "w") as f:
                f.write(text)
        for name, draw in plots:
            written.append(name)
            draw(temporary(path[name]))
        publish(args.output, files, written)
        args.published = True
    finally:
        for name in written:
            if os.path.exists(temporary(path[name])):
                os.remove(temporary(path[name]))
