"""The joint's back-calculation of scripts/liftoff-backcalc: the stiffness
AGG (Slabs/Shear stiffness, N/m^2) of an aggregate-interlock joint from the
load transfer efficiency a deflectometer test at the joint measured, LTE =
100 d_unloaded / d_loaded of the peaks at two sensors either side of it.
The slab's E and the bed's k are the scene's (back-calculated from a test
away from the joint). The start is Ioannides and Hammons' fit inverted for
f = AGG / (k l) (scripts/lte_fits.py; Crovetti's is printed beside it),
then AGG is fitted to the LTE by least squares over liftoff runs of the
scene."""

import math
import os

import numpy as np

import backcalc_fit
import lte_fits
from backcalc_basin import read_basin
from backcalc_scene import (DEFLECTOMETER, BackcalcError, SceneRuns,
                            scene_number, scene_values)
from liftoff_runs import read_csv


def sensor_index(offsets, target):
    near = [i for i, r in enumerate(offsets) if abs(r - target) <= 0.001]
    if not near:
        raise BackcalcError("--lte-sensors: no sensor at %g mm (+- 1 mm); "
                            "the basin has %s mm" % (1e3 * target, ", ".join(
                                "%g" % (1e3 * r) for r in offsets)))
    return near[0]


def measured_lte(args):
    """(offsets, indices of the loaded and the unloaded sensor, LTE)."""
    offsets, peaks = read_basin(args.measured)
    pair = [sensor_index(offsets, r) for r in args.lte_sensors]
    if peaks[pair[0]] <= 0:
        raise BackcalcError("the loaded sensor's peak, %g m, must be > 0"
                            % peaks[pair[0]])
    lte = 100 * peaks[pair[1]] / peaks[pair[0]]
    if not 0 < lte < 100:
        raise BackcalcError("the measured LTE, %.4g %%, is outside (0, 100) "
                            "%%, where a joint has a stiffness" % lte)
    return offsets, pair, lte


def scene_joint(args):
    """The scene's E, k and plate radius; it must have a joint."""
    values = scene_values(args.scene)
    if max(int(float(values.get("Slabs/Slabs along %s" % axis, "1")))
           for axis in "xy") < 2:
        raise BackcalcError("--joint needs a scene with a joint (Slabs/"
                            "Slabs along x or y >= 2); %s has none"
                            % args.scene)
    return (scene_number(args.scene, "Units/Young's modulus", "0"),
            scene_number(args.scene, "Units/Subgrade modulus", "0"),
            scene_number(args.scene, DEFLECTOMETER + "/Plate radius",
                         "0.15"))


def start(args, lte):
    """AGG from the fits, printed; Ioannides and Hammons' (which carries
    a / l) is the start."""
    E, k, a = scene_joint(args)
    ell = lte_fits.radius_of_relative_stiffness(E, args.thickness,
                                                args.poisson, k)
    f_crovetti = lte_fits.crovetti_inverse(lte)
    f_ih = lte_fits.ioannides_hammons_inverse(lte, a / ell)
    print("LTE %.4g %%: l = %.4g m, a/l = %.4g; f = AGG/(k l) = %.4g "
          "(Crovetti), %.4g (Ioannides-Hammons): AGG = %.6g, %.6g N/m^2"
          % (lte, ell, a / ell, f_crovetti, f_ih, f_crovetti * k * ell,
             f_ih * k * ell), flush=True)
    if args.start is not None:
        if len(args.start) != 1:
            raise BackcalcError("--start wants AGG, not %d values"
                                % len(args.start))
        print("start: AGG = %.6g N/m^2" % args.start[0], flush=True)
        return args.start[0], k * ell
    return f_ih * k * ell, k * ell


def lte_model(args, offsets, pair):
    runs = SceneRuns(args, offsets)

    def run(values, number):
        folder = runs.run(["Slabs/Shear stiffness=%r" % values[0]], number)
        peaks = [row["peak_w [m]"]
                 for row in read_csv(os.path.join(folder, "basin.csv"))]
        return [100 * peaks[pair[1]] / peaks[pair[0]]]
    return backcalc_fit.RunCache(run)


def backcalc_joint(args):
    offsets, pair, lte = measured_lte(args)
    agg0, kl = start(args, lte)
    os.makedirs(args.output, exist_ok=True)
    result = backcalc_fit.fit(
        [backcalc_fit.Parameter("AGG", "N/m^2", agg0)],
        lte_model(args, offsets, pair), [lte], 1.0, args.tolerance,
        args.max_runs, sigma_given=args.lte_uncertainty)
    agg, sigma = result.values[0], result.sigma[0]
    text = ("measured LTE: %.6g %% (sensors at %g and %g mm)\n"
            "fitted:      AGG = %.10g N/m^2 +- %.2g %% (for +- %g LTE "
            "points), f = AGG/(k l) = %.6g\n"
            "fitted LTE:  %.6g %% (residual %+.2e points)\n"
            "liftoff runs: %d (%s)\n"
            % (lte, 1e3 * offsets[pair[0]], 1e3 * offsets[pair[1]], agg,
               100 * sigma / agg, args.lte_uncertainty, agg / kl,
               result.fitted[0], result.fitted[0] - lte, result.runs,
               result.message))
    with open(os.path.join(args.output, "fit.txt"), "w") as f:
        f.write(text)
    print(text, end="")
    if not math.isfinite(sigma) or not np.isfinite(result.fitted[0]):
        raise BackcalcError("the LTE does not change with AGG here: is the "
                            "pair of sensors across the joint?")
