"""The static back-calculation of scripts/liftoff-backcalc: E and k from a
peak basin, the AREA method's closed form first, then a least-squares fit
over liftoff runs of the scene."""

import math
import os

import numpy as np

import backcalc_fit
from backcalc_scene import (BackcalcError, SceneRuns, make_output,
                            scene_force, scene_values)
from fwd_histories import HistoryError, number, read_rows

INCH = 0.0254
# The AREA4 sensors: 0, 12, 24 and 36 inches (the SHRP 0, 305, 610, 914 mm).
AREA_SENSORS = (0.0, 0.305, 0.610, 0.914)


def area_method(offsets, deflections, force, thickness, poisson):
    """(E, k, l) by the AREA method from the basin: offsets in m,
    deflections in m, the force in N, the thickness in m. The AREA4
    sensors are those within 5 mm of 0, 305, 610 and 914 mm."""
    d = []
    for target in AREA_SENSORS:
        near = [i for i, r in enumerate(offsets) if abs(r - target) <= 0.005]
        if not near:
            raise BackcalcError("the AREA method needs a sensor at %g mm "
                                "(+- 5 mm); the basin has %s mm"
                                % (1e3 * target, ", ".join(
                                    "%g" % (1e3 * r) for r in offsets)))
        # Python's floats: a huge reading gives inf, not numpy's warning.
        d.append(float(deflections[near[0]]))
    if d[0] <= 0:
        raise BackcalcError("the deflection under the load, %g m, must be "
                            "> 0" % d[0])
    area = 6 * (1 + 2 * d[1] / d[0] + 2 * d[2] / d[0] + d[3] / d[0])
    if not 0 < 36 - area < 1812.279133:
        raise BackcalcError("AREA4 = %g in is outside the AREA method's "
                            "range (below 36 in)" % area)
    ell_in = (math.log((36 - area) / 1812.279133) / -2.559340) ** 4.387009
    d0_star = 0.1245 * math.exp(-0.14707 * math.exp(-0.07565 * ell_in))
    ell = ell_in * INCH
    k = force * d0_star / (d[0] * ell**2)
    E = 12 * (1 - poisson**2) * k * ell**4 / thickness**3
    return E, k, ell


def area_start(args, offsets, peaks):
    """The AREA method on the peaks, printed; --start's E and k instead
    where given."""
    if args.start is not None:
        if len(args.start) not in (2, 3) or (len(args.start) == 3
                                             and not args.histories):
            raise BackcalcError("--start wants E,k%s, not %d values"
                                % (" or E,k,c" if args.histories else "",
                                   len(args.start)))
        print("start: E = %.6g Pa, k = %.6g N/m^3" % tuple(args.start[:2]),
              flush=True)
        return tuple(args.start[:2])
    E0, k0, ell = area_method(offsets, peaks, scene_force(args.scene),
                              args.thickness, args.poisson)
    print("AREA method: l = %.4g m, E = %.6g Pa, k = %.6g N/m^3"
          % (ell, E0, k0), flush=True)
    return E0, k0


class Basin:
    """The measured basin: offsets and peak deflections in m, and the
    peaks' times where the file has them (a liftoff basin.csv's t_peak)."""

    def __init__(self, path):
        try:
            header, rows = read_rows(path)
        except HistoryError as e:
            raise BackcalcError(str(e))
        names = [n.strip() for n in header]
        if len(rows) < 3:
            raise BackcalcError("the basin %s holds %d sensors; E and k need "
                                "at least 3" % (path, len(rows)))
        if len(names) < 2:
            raise BackcalcError("the basin %s has one column; it needs the "
                                "offset and the peak deflection" % path)
        peak = next((i for i, n in enumerate(names)
                     if n.startswith("peak_w")), 1)
        when = next((i for i, n in enumerate(names)
                     if n.startswith("t_peak")), None)
        try:
            table = [[number(row[i], path, line, names[i])
                      for i in (0, peak, when) if i is not None]
                     for line, row in rows]
        except HistoryError as e:
            raise BackcalcError(str(e))
        for (line, _), (offset, w, *_) in zip(rows, table):
            if offset < 0 or w < 0:
                raise BackcalcError(
                    "%s, line %d: the sensor at %g mm reads %s = %g m; "
                    "offsets and peak deflections (down positive) must be "
                    ">= 0" % (path, line, 1e3 * offset, names[peak], w)
                    if w < 0 else "%s, line %d: the offset %g m is "
                    "negative; it is the distance from the load's centre"
                    % (path, line, offset))
        table = np.array(table)
        self.offsets, self.peaks = table[:, 0], table[:, 1]
        self.times = table[:, 2] if when is not None else None

    def pulse_note(self, scene):
        """A warning when a static scene is to fit a pulse's peaks (their
        times are after 0), None otherwise."""
        if self.times is None or not np.any(self.times > 0) or scene_values(
                scene).get("Analysis/Type", "dynamic").strip() != "static":
            return None
        return ("warning: the basin's peaks come at t = %.4g to %.4g ms (its "
                "t_peak column), a pulse's; the static scene leaves out the "
                "test's inertia, which a static fit reads as a softer bed "
                "(doc/deflectometer.md): fit the histories (--histories) or "
                "with the dynamic scene" % (1e3 * self.times.min(),
                                            1e3 * self.times.max()))


def read_basin(path):
    """(offsets, peak deflections) of the measured basin."""
    basin = Basin(path)
    return basin.offsets, basin.peaks


def basin_model(args, offsets):
    """The peak basin of a liftoff run at (E, k)."""
    runs = SceneRuns(args, offsets)

    def run(values, serial):
        E, k = values
        folder = runs.run(["Units/Young's modulus=%r" % E,
                           "Units/Subgrade modulus=%r" % k], serial)
        return runs.table(folder, "basin.csv", ["peak_w [m]"])["peak_w [m]"]
    return backcalc_fit.RunCache(run, runs)


def modulus_parameters(E0, k0):
    return [backcalc_fit.Parameter("E", "Pa", E0),
            backcalc_fit.Parameter("k", "N/m^3", k0)]


def fitted_line(result):
    (E, k), (sE, sk) = result.values[:2], result.sigma[:2]
    return ("fitted:      E = %.10g Pa +- %.2g %%, k = %.10g N/m^3 +- %.2g %%"
            % (E, 100 * sE / E, k, 100 * sk / k))


def report(args, offsets, measured, start, result):
    """The lines of fit.txt; writes fit.csv."""
    lines = ["start: E = %.6g Pa, k = %.6g N/m^3" % start,
             fitted_line(result),
             "liftoff runs: %d (%s)" % (result.runs, result.message),
             "sensor [mm], measured [um], fitted [um], residual [um]"]
    with open(os.path.join(args.output, "fit.csv"), "w") as f:
        f.write("offset [m],measured [m],fitted [m],residual [m]\n")
        for r, m, w in zip(offsets, measured, result.fitted):
            f.write("%r,%r,%r,%r\n" % (r, m, w, w - m))
            lines.append("  %7.1f %10.3f %10.3f %+9.3f"
                         % (1e3 * r, 1e6 * m, 1e6 * w, 1e6 * (w - m)))
    return lines


def plot(path, offsets, measured, fitted, values):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(6, 4))
    axes.plot(1e3 * offsets, -1e6 * measured, "o", label="measured")
    axes.plot(1e3 * offsets, -1e6 * fitted, "-",
              label="liftoff, E = %.4g GPa, k = %.4g MPa/m"
              % (values[0] / 1e9, values[1] / 1e6))
    axes.set_xlabel("offset from the load [mm]")
    axes.set_ylabel("peak deflection [um] (down)")
    axes.grid(True, alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def backcalc_basin(args):
    basin = Basin(args.measured)
    offsets, measured = basin.offsets, basin.peaks
    start = area_start(args, offsets, measured)
    scatter = backcalc_fit.scatter_of(args.noise, measured, offsets)
    make_output(args.output)
    parameters = modulus_parameters(*start)
    result = backcalc_fit.fit(parameters, basin_model(args, offsets),
                              measured, measured[0], args.tolerance,
                              args.max_runs, scatter=scatter)
    error = backcalc_fit.publish(
        args.output, report(args, offsets, measured, start, result),
        parameters, result, [basin.pulse_note(args.scene)])
    if not args.no_plot:
        plot(os.path.join(args.output, "basin_fit.png"), offsets, measured,
             result.fitted, result.values)
    if error:
        raise BackcalcError(error)
