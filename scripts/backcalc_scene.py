"""The test's scene as scripts/liftoff-backcalc uses it: its entries (with
those of the files it includes), and one liftoff run of it with the fitted
values set."""

import os
import threading

from liftoff_runs import parse_parameters, read_csv, scene_including
from liftoff_workers import Workers

DEFLECTOMETER = "Loads/Deflectometer 1"


class BackcalcError(Exception):
    """A problem with the input, said in one line."""


def scene_values(scene, chain=()):
    """The scene's entries, those of the files it includes first (a
    later value wins, as in liftoff), each include relative to the folder
    of the file that names it."""
    path = os.path.abspath(scene)
    if path in chain:
        raise BackcalcError("the scene %s includes itself (%s)" % (
            chain[0], " -> ".join(list(chain) + [path])))
    values = {}
    try:
        with open(path, errors="replace") as f:
            for line in f:
                words = line.split("#", 1)[0].split(None, 1)
                if len(words) == 2 and words[0] in ("include", "INCLUDE"):
                    values.update(scene_values(os.path.join(
                        os.path.dirname(path), words[1].strip()),
                        chain + (path,)))
        values.update(parse_parameters(path))
    except (OSError, IndexError) as e:
        raise BackcalcError("the scene %s cannot be read%s: %s" % (
            scene, " (included by %s)" % chain[-1] if chain else "", e))
    return values


def scene_number(scene, entry, default, positive=True):
    """The scene's value of entry (Section/.../Entry) as a number, its
    default where the scene leaves it out."""
    text = scene_values(scene).get(entry, default)
    try:
        value = float(text)
    except ValueError:
        raise BackcalcError("the scene %s sets %s = %s, which "
                            "liftoff-backcalc reads as a number only"
                            % (scene, entry, text))
    if positive and not value > 0:
        raise BackcalcError("the scene %s must set %s > 0 (SI units), not %s"
                            % (scene, entry, text))
    return value


def make_output(folder):
    """The output folder, made if needed, once the input is checked."""
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as e:
        raise BackcalcError("--output %s cannot be made: %s" % (folder, e))


def check_includable(scene):
    """The scene can be included by the runs (its path holds no '#')."""
    try:
        scene_including(scene, [], "")
    except ValueError as e:
        raise BackcalcError("--scene: %s" % e)


def scene_force(scene):
    """The Peak force of the scene's Loads/Deflectometer 1 in N."""
    return scene_number(scene, DEFLECTOMETER + "/Peak force", "0")


def scene_joints(scene):
    """The names of the modelled plate's joints in liftoff's order, the
    order of a per-joint list in Slabs (doc/model.md, "Slabs and joints"):
    a rectangle's x1, x2, ..., y1, ... (those a half or quarter model
    meshes: on or beyond its symmetry plane), or a mesh file's curves of
    the condition `joint` in the order Boundary conditions/Mesh tags names
    them."""
    values = scene_values(scene)
    grid = []
    for axis in "xy":
        entry = "Slabs/Slabs along " + axis
        try:
            grid.append(int(values.get(entry, "1")))
        except ValueError:
            raise BackcalcError("the scene %s sets %s = %s, not a whole "
                                "number" % (scene, entry, values[entry]))
    if grid[0] * grid[1] > 1:
        symmetric = {"full": 0, "half": 1, "quarter": 2}.get(
            values.get("Discretization/Symmetry", "full").strip(), 0)
        # A joint at -1/2 + j/n of the side is meshed on a symmetric axis
        # when it lies on the plane (2 j = n) or beyond it.
        return ["%s%d" % (axis, j) for a, (axis, n) in enumerate(zip("xy",
                                                                     grid))
                for j in range(1, n) if a >= symmetric or 2 * j >= n]
    if values.get("Discretization/Shape", "").strip() != "mesh file":
        return []
    joints = []
    for tag in values.get("Boundary conditions/Mesh tags", "").split(","):
        name, _, condition = tag.partition(":")
        if condition.strip() == "joint":
            joints.append(name.strip())
    return joints


class SceneRuns:
    """liftoff runs of the scene, each in output/runs/runNNN, with the
    slab's thickness and Poisson ratio, the sensors' offsets and the fitted
    values set; the warnings of the runs that ended `completed with
    warnings`, by run number."""

    def __init__(self, args, offsets):
        self.args = args
        self.fixed = [
            "Units/Thickness=%r" % args.thickness,
            "Plate/Poisson ratio=%r" % args.poisson,
            "Output/VTU interval=0",
            DEFLECTOMETER + "/Sensor offsets="
            + ", ".join("%r" % float(r) for r in offsets)]
        self.warnings = {}
        self.lock = threading.Lock()
        # The runs go through liftoff workers (one process each, its
        # start-up paid once), the fit's side-by-side runs each in its own.
        self.workers = Workers(args.executable)

    def run(self, overrides, number):
        """The run's output folder, after the run."""
        folder = os.path.join(self.args.output, "runs", "run%03d" % number)
        try:
            # The template by reference: its includes and mesh file stay
            # relative to its own folder, as when liftoff runs it.
            text = scene_including(self.args.scene,
                                   self.fixed + list(overrides), folder)
        except ValueError as e:
            raise BackcalcError("--scene: %s" % e)
        # liftoff's own verdict on the scene (exit 1 with its "liftoff:
        # error in" line) repeats if run again; anything else (a signal,
        # an MPI start-up that aborted on a loaded machine, a crash) may
        # not, and is run once more.
        for attempt in (1, 2):
            try:
                code = self.workers.run(text, folder).code
            except OSError as e:
                raise BackcalcError("--executable %s cannot be run: %s"
                                    % (self.args.executable, e))
            if code == 0:
                self.note_warning(folder, number)
                return folder
            verdict = code == 1 and is_verdict(folder)
            cause = ("exit %d" % code if code > 0 else
                     "killed by signal %d" % -code)
            if verdict or attempt == 2:
                break
            print("liftoff run %d failed (%s, not liftoff's verdict on the "
                  "scene: %s); running it again"
                  % (number, cause, last_line(folder)), flush=True)
        raise BackcalcError("liftoff run %d failed (%s): %s (%s)"
                            % (number, cause, last_line(folder),
                               os.path.join(folder, "log.txt")))

    def note_warning(self, folder, number):
        # The lines themselves: a warning's text holds ": " too, which
        # parse_summary splits at.
        try:
            with open(os.path.join(folder, "summary.txt"),
                      errors="replace") as f:
                lines = {key: value.strip() for key, _, value in
                         (line.partition(": ") for line in f)}
        except OSError:
            lines = {}
        if lines.get("status") == "completed with warnings":
            with self.lock:
                self.warnings[number] = lines.get("warning", "(no text)")

    def table(self, folder, name, needed):
        """A CSV file the run wrote, as {column: list of floats}; a file
        without the needed columns (or without rows) names the run: an
        --executable that is not liftoff, a scene without the output."""
        path = os.path.join(folder, name)
        try:
            rows = read_csv(path)
            columns = {c: [row[c] for row in rows] for c in rows[0]}
        except (OSError, ValueError, KeyError, TypeError, IndexError) as e:
            raise BackcalcError("%s cannot be read (%s: %s): is --executable "
                                "%s liftoff?" % (path, type(e).__name__, e,
                                                 self.args.executable))
        missing = [c for c in needed if c not in columns]
        if missing:
            raise BackcalcError("%s has no column %s" % (path,
                                                         ", ".join(missing)))
        return columns


def log_lines(folder):
    try:
        with open(os.path.join(folder, "log.txt"), errors="replace") as f:
            return [line.strip() for line in f if line.strip()]
    except OSError:
        return []


def is_verdict(folder):
    """Whether the failed run's log holds liftoff's message on the scene
    (main.cc's report_failure)."""
    return any(line.startswith("liftoff: error in ")
               for line in log_lines(folder))


def last_line(folder):
    """The last line of a failed run's log: liftoff's one-line error."""
    lines = log_lines(folder)
    return lines[-1] if lines else "no log"
