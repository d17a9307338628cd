"""Running a scene from a Python test and reading what it wrote, one piece
of code for the tests that need it."""

import os
import shutil
import subprocess

import numpy as np


def run_scene(liftoff, work, name, text, options=(), ranks=1):
    """Write `text` to WORK/NAME.prm with its output in WORK/NAME and run
    it (with mpirun on `ranks` ranks if more than one); returns the output
    folder and the finished process (exit code, standard output and error
    as text)."""
    folder = os.path.join(work, name)
    with open(folder + ".prm", "w") as f:
        f.write(text + f"\nsubsection Output\n  set Directory = {folder}\nend\n")
    mpirun = []
    if ranks > 1:
        mpirun = [shutil.which("mpirun") or shutil.which("mpiexec"),
                  "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)]
    result = subprocess.run([*mpirun, liftoff, *options, folder + ".prm"],
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
    order; an empty cell (a load transfer with the load far from its
    joint) is NaN."""
    path = os.path.join(folder, "history.csv")
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.genfromtxt(path, delimiter=",", skip_header=1, ndmin=2)
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


def prm_text(sections, indent=""):
    """Nested dicts as prm text: a dict value is a subsection, any other
    value an entry."""
    lines = []
    for name, value in sections.items():
        if isinstance(value, dict):
            lines += [f"{indent}subsection {name}",
                      prm_text(value, indent + "  "), f"{indent}end"]
        else:
            lines.append(f"{indent}set {name} = {value}")
    return "\n".join(lines)


def merged(base, changes):
    """A copy of BASE (nested dicts, as prm_text takes them) with CHANGES
    put in: subsections merge, an entry of CHANGES replaces BASE's."""
    result = dict(base)
    for name, value in changes.items():
        if isinstance(value, dict) and isinstance(result.get(name), dict):
            result[name] = merged(result[name], value)
        else:
            result[name] = value
    return result


def scene_text(*parts):
    """The scene of a verification test as prm text: PARTS (nested dicts)
    merged one after the other over what these scenes share, Q2 elements
    and no VTU files."""
    sections = {"Discretization": {"Polynomial degree": 2},
                "Output": {"VTU interval": 0}}
    for part in parts:
        sections = merged(sections, part)
    return prm_text(sections) + "\n"


def point_load(k, x, y, magnitude):
    """Loads/Point load K at (x, y), as a part of scene_text."""
    return {"Loads": {f"Point load {k}": {"Magnitude": magnitude,
                                          "Position": f"{x}, {y}"}}}


def pressure(magnitude, intensity=None):
    """Loads/Pressure 1 on the whole plate, with its Intensity if given."""
    entries = {"Region": "whole plate", "Magnitude": magnitude}
    if intensity is not None:
        entries["Intensity"] = intensity
    return {"Loads": {"Pressure 1": entries}}


def pressed_plate(thickness_ratio, poisson_ratio, magnitude):
    """A static plate without foundation under a uniform pressure, no
    energies written: the closed-form tests of round plates."""
    return merged({"Analysis": {"Type": "static"},
                   "Plate": {"Thickness ratio": thickness_ratio,
                             "Poisson ratio": poisson_ratio},
                   "Foundation": {"Model": "none"},
                   "Output": {"Write energies": "false"}},
                  pressure(magnitude))


def static_disc_scene(radius, refinements, plate, foundation, load,
                      output):
    """A static scene of a Q2 disc under one point load (magnitude, x) on
    the x axis; PLATE, FOUNDATION and OUTPUT are entries of those
    subsections (no VTU files, no energies unless OUTPUT says so)."""
    magnitude, x = load
    return scene_text(
        {"Analysis": {"Type": "static"}, "Plate": plate,
         "Foundation": foundation,
         "Discretization": {"Shape": "disc", "Radius": radius,
                            "Global refinements": refinements},
         "Output": {"Write energies": "false"}},
        point_load(1, x, 0, magnitude), {"Output": output})
