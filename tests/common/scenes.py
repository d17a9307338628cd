"""Running a scene from a Python test and reading what it wrote, one piece
of code for the tests that need it."""

import os
import subprocess

import numpy as np


def run_scene(liftoff, work, name, text, options=()):
    """Write `text` to WORK/NAME.prm with its output in WORK/NAME and run
    it; returns the output folder and the finished process (exit code,
    standard output and error as text)."""
    folder = os.path.join(work, name)
    with open(folder + ".prm", "w") as f:
        f.write(text + f"\nsubsection Output\n  set Directory = {folder}\nend\n")
    result = subprocess.run([liftoff, *options, folder + ".prm"],
                            capture_output=True, text=True)
    return folder, result


def run_scene_or_fail(liftoff, work, name, text):
    """run_scene for a scene that must run: a failure raises, with the
    run's message."""
    folder, result = run_scene(liftoff, work, name, text)
    if result.returncode != 0:
        raise RuntimeError(f"{name} failed: {result.stderr.strip()}")
    return folder


def read_history(folder):
    """FOLDER/history.csv as columns (numpy arrays) by name, in the file's
    order."""
    path = os.path.join(folder, "history.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: data[:, k] for k, name in enumerate(header)}
