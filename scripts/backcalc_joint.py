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

import numpy as np

import backcalc_fit
import lte_fits
from backcalc_basin import read_basin
from backcalc_scene import (DEFLECTOMETER, BackcalcError, SceneRuns,
                            make_output, scene_joints, scene_number,
                            scene_values)


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


class Joint:
    """The joint the test is at (--joint-name, or the scene's only one),
    and the scene's Slabs/Shear stiffness as one value per joint, of which
    the fit changes this joint's only."""

    def __init__(self, args):
        scene = args.scene
        names = scene_joints(scene)
        if not names:
            raise BackcalcError(
                "--joint needs a scene with a joint (Slabs/Slabs along x or "
                "y >= 2, or a mesh file's curve of the condition joint in "
                "Boundary conditions/Mesh tags); %s has none" % scene)
        if args.joint_name is None and len(names) > 1:
            raise BackcalcError("the scene %s has the joints %s: name the one "
                                "the test is at with --joint-name"
                                % (scene, ", ".join(names)))
        self.name = args.joint_name or names[0]
        if self.name not in names:
            raise BackcalcError("--joint-name %s: the scene %s has the joints "
                                "%s" % (self.name, scene, ", ".join(names)))
        values = scene_values(scene)
        tied = [t.strip() for t in
                values.get("Slabs/Tied joints", "").split(",")]
        if self.name in tied:
            raise BackcalcError("the joint %s is tied in %s (Slabs/Tied "
                                "joints): it has no stiffness to fit"
                                % (self.name, scene))
        text = values.get("Slabs/Shear stiffness", "0")
        try:
            given = [float(v) for v in text.split(",")]
        except ValueError:
            given = []
        if len(given) not in (1, len(names)) or not all(
                0 <= v < math.inf for v in given):
            raise BackcalcError("the scene %s sets Slabs/Shear stiffness = %s;"
                                " its joints %s want one value >= 0 or one "
                                "per joint" % (scene, text, ", ".join(names)))
        self.names = names
        self.stiffnesses = given * len(names) if len(given) == 1 else given
        self.index = names.index(self.name)

    def override(self, agg):
        values = list(self.stiffnesses)
        values[self.index] = agg
        return "Slabs/Shear stiffness=" + ", ".join("%r" % v for v in values)

    def others(self):
        """The other joints and their stiffnesses, as the report says."""
        kept = ", ".join("%s %.6g N/m^2" % (n, v) for n, v in zip(
            self.names, self.stiffnesses) if n != self.name)
        return "the others kept: " + kept if kept else "the scene's only one"


def scene_moduli(args):
    """The scene's E, k and plate radius."""
    return (scene_number(args.scene, "Units/Young's modulus", "0"),
            scene_number(args.scene, "Units/Subgrade modulus", "0"),
            scene_number(args.scene, DEFLECTOMETER + "/Plate diameter",
                         "0.3") / 2)


def start(args, lte):
    """AGG from the fits, printed; Ioannides and Hammons' (which carries
    a / l) is the start."""
    E, k, a = scene_moduli(args)
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


def lte_model(args, offsets, pair, joint):
    runs = SceneRuns(args, offsets)

    def run(values, number):
        folder = runs.run([joint.override(values[0])], number)
        peaks = runs.table(folder, "basin.csv", ["peak_w [m]"])["peak_w [m]"]
        return [100 * peaks[pair[1]] / peaks[pair[0]]]
    return backcalc_fit.RunCache(run, runs)


def backcalc_joint(args):
    offsets, pair, lte = measured_lte(args)
    joint = Joint(args)
    agg0, kl = start(args, lte)
    print("to fit: the Shear stiffness of the joint %s (%s)"
          % (joint.name, joint.others()), flush=True)
    make_output(args.output)
    parameters = [backcalc_fit.Parameter("AGG", "N/m^2", agg0)]
    result = backcalc_fit.fit(
        parameters, lte_model(args, offsets, pair, joint), [lte], 1.0,
        args.tolerance, args.max_runs, sigma_given=args.lte_uncertainty)
    agg, sigma = result.values[0], result.sigma[0]
    lines = ["measured LTE: %.6g %% (sensors at %g and %g mm)"
             % (lte, 1e3 * offsets[pair[0]], 1e3 * offsets[pair[1]]),
             "fitted:      AGG = %.10g N/m^2 +- %.2g %% (for +- %g LTE "
             "points), f = AGG/(k l) = %.6g; joint %s (%s)"
             % (agg, 100 * sigma / agg, args.lte_uncertainty, agg / kl,
                joint.name, joint.others()),
             "fitted LTE:  %.6g %% (residual %+.2e points)"
             % (result.fitted[0], result.fitted[0] - lte),
             "liftoff runs: %d (%s)" % (result.runs, result.message)]
    backcalc_fit.publish(args.output, lines, parameters, result)
    if not math.isfinite(sigma) or not np.isfinite(result.fitted[0]):
        raise BackcalcError("the LTE does not change with the joint %s's "
                            "AGG here: is the pair of sensors across it?"
                            % joint.name)
