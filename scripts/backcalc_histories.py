"""The dynamic back-calculation of scripts/liftoff-backcalc: E, k and the
bed's dashpots (Units/Dashpot coefficient c, Pa s/m) from the sensors'
measured time histories (scripts/fwd_histories.py has the format), by a
least-squares fit of the whole histories over liftoff runs of the scene (a
time integration of the pulse), from the AREA method on their peaks."""

import math
import os

import numpy as np

import backcalc_basin
import backcalc_fit
from backcalc_scene import (DEFLECTOMETER, BackcalcError, SceneRuns,
                            make_output, scene_number, scene_values)
from fwd_histories import (HistoryError, check_window, read_histories,
                           write_histories)

# The times with a deflection the fit needs: at one time the sensors give
# one basin, in which the bed's springs and its dashpots act as one
# stiffness (over the first step k + c gamma / (beta dt), k + 2 c / dt
# with the default Newmark); a second time parts them
# (then the conditioning judges how well).
TIMES_NEEDED = 2


def measured_histories(args):
    """(times, offsets, deflections) of the measured file, checked against
    the scene's time window and pulse."""
    if scene_values(args.scene).get("Analysis/Type", "dynamic") != "dynamic":
        raise BackcalcError("--histories needs a scene with Analysis/Type = "
                            "dynamic; %s is static" % args.scene)
    end_time = scene_number(args.scene, "Time integration/End time", "1")
    duration = scene_number(args.scene, DEFLECTOMETER + "/Duration", "1")
    try:
        times, offsets, values = read_histories(args.measured)
        check_window(times, end_time, duration, args.measured)
    except HistoryError as e:
        raise BackcalcError(str(e))
    moved = times[np.any(values != 0, axis=1)]
    if len(moved) < TIMES_NEEDED:
        raise BackcalcError(
            "%s holds %d time%s with a deflection (%s); k and c need %d at "
            "least: at one time the bed's springs and dashpots act as one "
            "stiffness, k + 2 c / dt over the first step"
            % (args.measured, len(moved), "" if len(moved) == 1 else "s",
               ", ".join("%g s" % t for t in moved) or "none",
               TIMES_NEEDED))
    return times, offsets, values


def history_model(args, times, offsets):
    """The sensors' histories of a liftoff run at (E, k, c), at the
    measured times (linear in time between the run's steps), one row per
    time."""
    runs = SceneRuns(args, offsets)

    def run(values, number):
        E, k, c = values
        folder = runs.run(["Units/Young's modulus=%r" % E,
                           "Units/Subgrade modulus=%r" % k,
                           "Units/Dashpot coefficient=%r" % c], number)
        columns = runs.table(folder, "history.csv", ["t [s]"])
        names = [n for n in columns if n.startswith("d(")]
        if len(names) != len(offsets):
            raise BackcalcError("%s has %d sensor columns, not the %d set"
                                % (os.path.join(folder, "history.csv"),
                                   len(names), len(offsets)))
        return np.array([np.interp(times, columns["t [s]"], columns[n])
                         for n in names]).T
    return backcalc_fit.RunCache(run, runs)


class Flat:
    """The model's histories as one vector (the fit's residuals)."""

    def __init__(self, model):
        self.model, self.numbers = model, model.numbers

    def __call__(self, values):
        return self.model(values).ravel()

    def runs(self):
        return self.model.runs()

    def warnings(self):
        return self.model.warnings()


def parameters(args, start):
    """E and k from the AREA start; c from --damping-start, a fraction of
    the critical 2 sqrt(k rho h) of the slab bouncing on its bed, which is
    also the scale of c's variable."""
    E0, k0 = start
    rho = scene_number(args.scene, "Units/Density", "0")
    critical = 2 * math.sqrt(k0 * rho * args.thickness)
    c0 = args.damping_start * critical
    if args.start is not None and len(args.start) == 3:
        c0 = args.start[2]
    print("dashpots: start c = %.6g Pa s/m (%.4g of the critical %.6g)"
          % (c0, c0 / critical, critical), flush=True)
    return backcalc_basin.modulus_parameters(E0, k0) + [
        backcalc_fit.Parameter("c", "Pa s/m", c0, scale=critical)]


def report(offsets, measured, start, result):
    """The lines of fit.txt."""
    fitted = result.fitted.reshape(measured.shape)
    c, sc = result.values[2], result.sigma[2]
    lines = ["start: E = %.6g Pa, k = %.6g N/m^3" % start,
             backcalc_basin.fitted_line(result)
             + ", c = %.10g Pa s/m +- %.2g Pa s/m" % (c, sc),
             "liftoff runs: %d (%s)" % (result.runs, result.message),
             "sensor [mm], measured peak [um], fitted peak [um], "
             "rms residual over time [um]"]
    for j, r in enumerate(offsets):
        rms = math.sqrt(np.mean((fitted[:, j] - measured[:, j]) ** 2))
        lines.append("  %7.1f %10.3f %10.3f %9.3f"
                     % (1e3 * r, 1e6 * measured[:, j].max(),
                        1e6 * fitted[:, j].max(), 1e6 * rms))
    return lines


def plot(path, times, offsets, measured, fitted, values):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(7, 4.5))
    for j, r in enumerate(offsets):
        colour = "C%d" % (j % 10)
        axes.plot(1e3 * times, -1e6 * measured[:, j], ".", color=colour,
                  markersize=3)
        axes.plot(1e3 * times, -1e6 * fitted[:, j], "-", color=colour,
                  label="%g mm" % (1e3 * r))
    axes.set_title("measured (dots) and fitted: E = %.4g GPa, k = %.4g "
                   "MPa/m, c = %.3g kPa s/m" % (values[0] / 1e9,
                                                values[1] / 1e6,
                                                values[2] / 1e3),
                   fontsize=9)
    axes.set_xlabel("t [ms]")
    axes.set_ylabel("deflection [um] (down)")
    axes.grid(True, alpha=0.3)
    axes.legend(fontsize=7, ncol=2)
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def backcalc_histories(args):
    if not 0 <= args.damping_start < math.inf:
        raise BackcalcError("--damping-start = %g must be >= 0"
                            % args.damping_start)
    times, offsets, measured = measured_histories(args)
    start = backcalc_basin.area_start(args, offsets, measured.max(axis=0))
    fitted_parameters = parameters(args, start)
    scatter = backcalc_fit.scatter_of(
        args.noise, np.abs(measured).max(axis=0), offsets)
    make_output(args.output)
    model = Flat(history_model(args, times, offsets))
    result = backcalc_fit.fit(fitted_parameters, model, measured.ravel(),
                              np.abs(measured).max(), args.tolerance,
                              args.max_runs,
                              scatter=np.tile(scatter, len(times)))
    error = backcalc_fit.publish(args.output,
                                 report(offsets, measured, start, result),
                                 fitted_parameters, result)
    fitted = result.fitted.reshape(measured.shape)
    write_histories(os.path.join(args.output, "histories_fit.csv"), times,
                    offsets, [("measured", measured), ("fitted", fitted)])
    if not args.no_plot:
        plot(os.path.join(args.output, "histories_fit.png"), times, offsets,
             measured, fitted, result.values)
    if error:
        raise BackcalcError(error)
