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


def read_profile(folder):
    """The first profile of FOLDER/profiles.csv: its arc length s and w."""
    data = np.loadtxt(os.path.join(folder, "profiles.csv"), delimiter=",",
                      skiprows=1, ndmin=2)
    first = data[:, 0] == data[0, 0]
    return data[first, 1], data[first, 4]


def first_sign_change(s, w):
    """Where w along a profile first changes sign, by linear interpolation
    between the two profile points around it (None if it never does)."""
    changes = np.nonzero(np.sign(w[1:]) != np.sign(w[:-1]))[0]
    if changes.size == 0:
        return None
    i = changes[0]
    return s[i] - w[i] * (s[i + 1] - s[i]) / (w[i + 1] - w[i])
