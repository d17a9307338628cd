"""What every script that runs liftoff needs: a scene with overrides, one
run in its own process, and the run's summary.txt and CSV files read back.

Scripts in scripts/ and benchmarks/ import this module (benchmarks add
scripts/ to sys.path) so that there is one way to override a parameter and
one parser of liftoff's output files.
"""

import csv
import os
import subprocess


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
    """The scene file's text, the overrides, and the output directory."""
    with open(scene_file) as f:
        text = f.read()
    return text + override_text(list(overrides)
                                + ["Output/Directory=" + directory])


def run_scene(executable, text, directory, ranks=1, log_name="log.txt",
              check=True):
    """Run liftoff on the scene text (written to directory/scene.prm) in its
    own process; returns the exit code."""
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
        result = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT)
    if check and result.returncode != 0:
        raise RuntimeError("liftoff failed (exit %d) in %s; see %s"
                           % (result.returncode, directory,
                              os.path.join(directory, log_name)))
    return result.returncode


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


def parse_parameters(path):
    """A ParameterHandler file such as used_parameters.prm as a dict that
    maps "Section/.../Entry" to the value's text (the last set wins, as in
    ParameterHandler)."""
    values, sections = {}, []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end":
                sections.pop()
            elif line.startswith("set "):
                entry, _, value = line[len("set "):].partition("=")
                values["/".join(sections + [entry.strip()])] = value.strip()
    return values
