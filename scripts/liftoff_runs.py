"""What every script that runs liftoff needs: a scene with overrides, one
run in its own process, and the run's summary.txt and CSV files read back.

Scripts in scripts/ and benchmarks/ import this module (benchmarks add
scripts/ to sys.path) so that there is one way to override a parameter and
one parser of liftoff's output files.
"""

import csv
import os
import subprocess
import time


def override_text(overrides):
    """ParameterHandler text that sets each "Section/.../Entry=value";
    appended to a scene it wins, since the last value set for an entry is
    the one kept."""
    text = ""
    for override in overrides:
        path, value = override.split("=", 1)
        *sections, entry = path.split("/")
        if not sections:
            raise ValueError("an override wants Section/Entry=value, got "
                             + override)
        text += "\n"
        for s in sections:
            text += "subsection %s\n" % s.strip()
        text += "  set %s = %s\n" % (entry.strip(), value.strip())
        text += "end\n" * len(sections)
    return text


def scene_with_overrides(scene_file, overrides, directory):
    """The scene file's text, the overrides, and the output directory. The
    text is run from another folder, so its relative include lines are
    made absolute (against the scene file's folder, as liftoff resolves
    them when it runs the file itself)."""
    folder = os.path.dirname(os.path.abspath(scene_file))
    lines = []
    with open(scene_file) as f:
        for line in f:
            stripped = line.strip()
            if stripped.startswith("include "):
                target = stripped[len("include "):].split("#", 1)[0].strip()
                if target and not os.path.isabs(target):
                    line = "include %s\n" % os.path.join(folder, target)
            lines.append(line)
    return "".join(lines) + override_text(
        list(overrides) + ["Output/Directory=" + directory])


def scene_including(scene_file, overrides, directory):
    """A scene that includes the scene file by its absolute path, then the
    overrides and the output directory: liftoff resolves the file's own
    relative includes and mesh file against the file's folder, as when it
    is run directly, wherever this text is written."""
    path = os.path.abspath(scene_file)
    if "#" in path or "\n" in path:
        # An include line ends at a comment sign; such a path cannot be
        # included.
        raise ValueError("the scene's path %s holds a '#' or a line break, "
                         "which an include line cannot carry" % path)
    return "include %s\n" % path + override_text(
        list(overrides) + ["Output/Directory=" + directory])


def run_scene(executable, text, directory, ranks=1, log_name="log.txt",
              check=True):
    """Run liftoff on the scene text (written to directory/scene.prm) in its
    own process; returns the exit code."""
    code, _, _ = run_scene_timed(executable, text, directory, ranks, log_name)
    if check and code != 0:
        raise RuntimeError("liftoff failed (exit %d) in %s; see %s"
                           % (code, directory,
                              os.path.join(directory, log_name)))
    return code


def run_scene_timed(executable, text, directory, ranks=1,
                    log_name="log.txt"):
    """run_scene without the check, as (exit code, wall seconds, CPU
    seconds of the process and its children). The CPU time is the child's
    own (os.wait4), so runs made side by side from threads are each timed
    alone; under mpirun it includes every rank, which mpirun waits for."""
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "scene.prm")
    with open(prm, "w") as f:
        f.write(text)
    # The directory is the script's own: a run replaces the results that an
    # earlier run of the script left there (liftoff refuses that otherwise).
    command = [executable, "--overwrite", prm]
    if ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe",
                   "-np", str(ranks)] + command
    with open(os.path.join(directory, log_name), "w") as log:
        start = time.perf_counter()
        process = subprocess.Popen(command, stdout=log,
                                   stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
        elapsed = time.perf_counter() - start
        # Popen must not wait for the pid that wait4 has reaped.
        process.returncode = os.waitstatus_to_exitcode(status)
    return (process.returncode, elapsed, usage.ru_utime + usage.ru_stime)
def parse_summary(path):
    """summary.txt as (values, sections): values maps each "key: value" line
    to its text, sections maps the TimerOutput sections to seconds."""
    values, sections = {}, {}
    in_sections = False
    with open(path) as f:
        for line in f:
            if line.startswith("wall time by section"):
                in_sections = True
                continue
            key, _, value = line.strip().rpartition(": ")
            if in_sections and line.startswith("  "):
                sections[key] = float(value)
            else:
                in_sections = False
                values[key] = value
    return values, sections


def read_csv(path):
    """A CSV that liftoff wrote, as a list of dicts of floats."""
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()}
                for row in csv.DictReader(f)]


def read_table(path):
    """A CSV that liftoff wrote, as a pandas DataFrame of floats (what the
    study tool reads: parsed in C, a hundred histories in well under a
    second)."""
    import pandas
    table = pandas.read_csv(path, dtype=float)
    # A run of a scene in SI units has its time as "t [s]": the study's time
    # axis is then in seconds, the unit of that scene's Time step.
    return table.rename(columns={"t [s]": "tau"})


def used_parameters(directory):
    """The parameters a run used, as a dict that maps "Section/.../Entry" to
    the value's text. The one place that knows the format of what a run
    writes about its parameters (today used_parameters.prm in
    ParameterHandler's text format)."""
    return parse_parameters(os.path.join(directory, "used_parameters.prm"))


def parse_parameters(path):
    """A ParameterHandler file such as used_parameters.prm as a dict that
    maps "Section/.../Entry" to the value's text (the last set wins, as in
    ParameterHandler)."""
    with open(path) as f:
        return parameter_values(f.read())


def parameter_values(text):
    """ParameterHandler text (a scene with its overrides) as the dict of
    parse_parameters; an entry the text does not set is absent."""
    values, sections = {}, []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line.startswith("subsection "):
            sections.append(line[len("subsection "):].strip())
        elif line == "end" and sections:
            sections.pop()
        elif line.startswith("set "):
            entry, _, value = line[len("set "):].partition("=")
            values["/".join(sections + [entry.strip()])] = value.strip()
    return values
