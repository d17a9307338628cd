"""The test's scene as scripts/liftoff-backcalc uses it: its entries (with
those of the files it includes), and one liftoff run of it with the fitted
values set."""

import os

from liftoff_runs import parse_parameters, run_scene, scene_with_overrides

DEFLECTOMETER = "Loads/Deflectometer 1"


class BackcalcError(Exception):
    """A problem with the input, said in one line."""


def scene_values(scene):
    """The scene's entries, those of the files it includes first (a
    later value wins, as in liftoff)."""
    values = {}
    with open(scene) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if len(words) == 2 and words[0] == "include":
                values.update(scene_values(os.path.join(
                    os.path.dirname(os.path.abspath(scene)), words[1])))
    values.update(parse_parameters(scene))
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


def scene_force(scene):
    """The Peak force of the scene's Loads/Deflectometer 1 in N."""
    return scene_number(scene, DEFLECTOMETER + "/Peak force", "0")


class SceneRuns:
    """liftoff runs of the scene, each in output/runs/runNNN, with the
    slab's thickness and Poisson ratio, the sensors' offsets and the fitted
    values set."""

    def __init__(self, args, offsets):
        self.args = args
        self.fixed = [
            "Units/Thickness=%r" % args.thickness,
            "Plate/Poisson ratio=%r" % args.poisson,
            "Output/VTU interval=0",
            DEFLECTOMETER + "/Sensor offsets="
            + ", ".join("%r" % float(r) for r in offsets)]

    def run(self, overrides, number):
        """The run's output folder, after the run."""
        folder = os.path.join(self.args.output, "runs", "run%03d" % number)
        text = scene_with_overrides(self.args.scene,
                                    self.fixed + list(overrides), folder)
        # A second try: on a loaded machine a run has once failed where the
        # same run succeeded again; a scene liftoff refuses fails twice.
        for attempt in (1, 2):
            try:
                run_scene(self.args.executable, text, folder)
                return folder
            except (RuntimeError, OSError) as e:
                failure = "%s: %s" % (e, last_line(folder))
            if attempt == 1:
                print("liftoff run %d failed (%s); running it again"
                      % (number, failure), flush=True)
        raise BackcalcError(failure)


def last_line(folder):
    """The last line of a failed run's log: liftoff's one-line error."""
    try:
        with open(os.path.join(folder, "log.txt")) as f:
            lines = [line.strip() for line in f if line.strip()]
    except OSError:
        lines = []
    return lines[-1] if lines else "no log"
