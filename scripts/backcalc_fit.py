"""A least-squares fit whose model is a liftoff run: the part of
scripts/liftoff-backcalc that every back-calculation (the peak basin, the
time histories, the joint's load transfer) shares.

Each fitted quantity is a Parameter, whose variable in the fit is ln(value)
(a modulus: positive, its scale unknown) or value / scale with the bound
value >= 0 (a damping coefficient, which may be 0). The Jacobian is by
forward differences of the variables (one liftoff run per parameter, run
side by side), and the uncertainty of each value is one standard deviation
from it at the end: cov = s^2 (J^T J)^-1, s^2 the residuals' sum of
squares over (residuals - parameters), or a given s when the fit has no
degrees of freedom left (one LTE, one joint stiffness).

Those error bars say how far noise of the residuals' own size moves the
values; they say nothing of a model that cannot fit (a bias) or of values
the data do not separate. So every fit is also judged by the residuals
against the scatter the data allow (chi^2 over its degrees of freedom,
and its probability) and by the conditioning of the Jacobian with each
column scaled to length 1 (its singular values; the smallest one's
direction names the values the data cannot tell apart).
"""

import concurrent.futures
import math
import os
import threading

import numpy as np

from backcalc_scene import BackcalcError


class Parameter:
    """One fitted quantity: its name and unit for the printed lines, its
    start, and how the fit's variable maps to it."""

    def __init__(self, name, unit, start, scale=None):
        self.name, self.unit, self.start = name, unit, start
        # scale None: the variable is ln(value); else value / scale >= 0.
        self.scale = scale

    def variable(self, value):
        return math.log(value) if self.scale is None else value / self.scale

    def value(self, x):
        return math.exp(x) if self.scale is None else x * self.scale

    def derivative(self, x):
        """d value / d variable, which turns the variable's standard
        deviation into the value's."""
        return math.exp(x) if self.scale is None else self.scale

    def lower(self):
        return -math.inf if self.scale is None else 0.0


class RunCache:
    """run(values, number) -> the model's numbers, once per set of values
    (the fit asks for its last point again), each run numbered in the
    order asked for."""

    def __init__(self, run, scene_runs):
        self.run, self.scene_runs = run, scene_runs
        self.known, self.numbers = {}, {}
        self.lock = threading.Lock()

    def warnings(self):
        """{run number: the warning of a run that ended `completed with
        warnings`}."""
        return dict(self.scene_runs.warnings)

    def __call__(self, values):
        values = tuple(values)
        with self.lock:
            if values not in self.numbers:
                self.numbers[values] = len(self.numbers) + 1
        if values not in self.known:
            self.known[values] = np.asarray(
                self.run(values, self.numbers[values]), dtype=float)
        return self.known[values]

    def runs(self):
        return len(self.numbers)


# A condition number of the column-scaled Jacobian above this leaves some
# combination of the values unfixed: 1 % of noise moves it by 10 times its
# size or more. The differences' round-off keeps a singular Jacobian's
# number finite (2.1e6 for histories of one time); well-posed fits measure
# 5 to 51.
CONDITION_LIMIT = 1e3
# The residuals are called larger than the data's scatter when chi^2 that
# large comes less than once in a thousand fits of the right model.
CHI2_PROBABILITY = 1e-3


class FitResult:
    def __init__(self, values, sigma, fitted, message, runs):
        self.values, self.sigma, self.fitted = values, sigma, fitted
        self.message, self.runs = message, runs
        self.singular = self.weak = self.chi2 = self.dof = None
        self.scaled_rms = self.probability = self.sigma_scatter = None
        self.run_of_fit, self.warnings = None, {}

    def condition(self):
        s = self.singular
        return math.inf if s is None or not s[-1] > 0 else s[0] / s[-1]


def scatter_of(noise, peaks, offsets):
    """Each sensor's standard deviation in m from --noise, (value, share):
    a value in m, or a share of the sensor's peak."""
    value, share = noise
    if not share:
        return np.full(len(peaks), value)
    scatter = value * np.abs(peaks)
    if not np.all(scatter > 0):
        # chi^2 would divide by it.
        raise BackcalcError("--noise %g %%: the sensor at %g mm peaks at 0, "
                            "a share of which is no scatter; give --noise "
                            "in m" % (100 * value, 1e3 * offsets[int(
                                np.argmin(scatter))]))
    return scatter


def describe(parameters, values):
    return ", ".join("%s = %.6g %s" % (p.name, v, p.unit)
                     for p, v in zip(parameters, values))


def fit(parameters, model, measured, scale, tolerance, max_runs,
        sigma_given=None, scatter=None):
    """least_squares of (model(values) - measured) / scale from the
    parameters' starts; model is a RunCache. Prints a line per run.
    scatter: each measured value's standard deviation (the same unit),
    for chi^2."""
    # scipy's import takes a third of a second: not for refused input.
    from scipy import optimize
    measured = np.asarray(measured, dtype=float)

    def values_of(x):
        return tuple(p.value(xi) for p, xi in zip(parameters, x))

    def residuals(x, quiet=False):
        values = values_of(x)
        r = (model(values) - measured) / scale
        if quiet:
            return r
        print("liftoff run %3d: %s, rms residual %.3e"
              % (model.numbers[values], describe(parameters, values),
                 math.sqrt(np.mean(r * r))), flush=True)
        return r

    def jacobian(x):
        # Steps of 1e-5 in each variable: liftoff's outputs are exact to
        # about 1e-10 of their size. The columns are runs side by side.
        h = 1e-5
        base = residuals(x, quiet=True)
        steps = [x + h * np.eye(len(x))[i] for i in range(len(x))]
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            columns = list(pool.map(lambda y: (residuals(y) - base) / h,
                                    steps))
        return np.array(columns).T

    x0 = np.array([p.variable(p.start) for p in parameters])
    lower = np.array([p.lower() for p in parameters])
    # dogbox: a value that fits at its bound (no dashpots) lands on it;
    # trf's interior steps only halve the distance each time.
    result = optimize.least_squares(
        residuals, x0, jac=jacobian, bounds=(lower, np.inf), method="dogbox",
        xtol=tolerance, ftol=1e-12, gtol=1e-12, max_nfev=max_runs)
    values = values_of(result.x)
    fitted = model(values)
    r = (fitted - measured) / scale
    dof = len(r) - len(parameters)
    s2 = sigma_given**2 if sigma_given is not None else (
        float(r @ r) / dof if dof > 0 else math.inf)
    sigma = deviations(parameters, result.x, result.jac, math.sqrt(s2))
    found = FitResult(values, sigma, fitted, result.message, model.runs())
    found.singular, found.weak = scaled_singular(result.jac)
    if scatter is not None and dof > 0:
        scatter = np.broadcast_to(scatter, measured.shape)
        # What the data's own scatter alone allows: larger than the error
        # bars above when the residuals are smaller than the scatter.
        weighted = result.jac * (scale / scatter)[:, None]
        found.sigma_scatter = deviations(parameters, result.x, weighted, 1.0)
        z = (fitted - measured) / scatter
        found.chi2, found.dof = float(z @ z), dof
        found.scaled_rms = math.sqrt(found.chi2 / dof)
        from scipy import stats
        found.probability = float(stats.chi2.sf(found.chi2, dof))
    found.run_of_fit = model.numbers[values]
    found.warnings = model.warnings()
    return found


def deviations(parameters, x, jacobian, s):
    """Each value's standard deviation, cov = s^2 (J^T J)^-1 of the
    variables, turned into the values'."""
    try:
        cov = s**2 * np.linalg.inv(jacobian.T @ jacobian)
        return [abs(p.derivative(xi)) * math.sqrt(c) for p, xi, c
                in zip(parameters, x, np.diag(cov))]
    except (np.linalg.LinAlgError, ValueError):
        return [math.inf] * len(parameters)


def scaled_singular(jacobian):
    """The singular values of the Jacobian with each column scaled to
    length 1 (largest first), and the right singular vector of the
    smallest: a column of zeros gives a singular value 0."""
    jacobian = np.asarray(jacobian, dtype=float)
    norms = np.linalg.norm(jacobian, axis=0)
    if not np.all(np.isfinite(jacobian)):
        return np.zeros(jacobian.shape[1]), np.ones(jacobian.shape[1])
    scaled = jacobian / np.where(norms > 0, norms, 1)
    _, singular, vt = np.linalg.svd(scaled, full_matrices=False)
    return singular, vt[-1]


def spread(parameter, value, deviation):
    """"E +- 1.2 %" for a modulus, "c +- 30 Pa s/m" for a coefficient."""
    if parameter.scale is None:
        return "%s +- %.2g %%" % (parameter.name, 100 * deviation / value)
    return "%s +- %.2g %s" % (parameter.name, deviation, parameter.unit)


def judgement(parameters, result):
    """Lines that say what the error bars leave out: the residuals against
    the data's scatter, whether the data separate the values, and the
    liftoff runs that ended `completed with warnings`; and the error, if
    the data do not fix the values (None otherwise)."""
    lines, error = [], None
    if len(parameters) > 1:
        cond = result.condition()
        lines.append("conditioning: the scaled Jacobian's singular values "
                     "%s (condition number %.3g; above %.0e the data do not"
                     " separate the values)" % (", ".join(
                         "%.3g" % v for v in result.singular), cond,
                         CONDITION_LIMIT))
        if not cond <= CONDITION_LIMIT:
            mixed = [p.name for p, w in zip(parameters, result.weak)
                     if abs(w) > 0.2]
            error = ("the data do not separate %s: the scaled Jacobian's "
                     "condition number is %.3g (above %.0e), so their "
                     "values and error bars mean nothing; measure more "
                     "(longer histories, more sensors) or fit fewer values"
                     % (" and ".join(mixed), cond, CONDITION_LIMIT))
            lines.append("not identified: " + error)
    if result.chi2 is not None:
        rms = result.scaled_rms
        lines.append("residuals against the data's scatter: chi^2/dof = "
                     "%.3g (%d degrees of freedom, probability %.2g), RMS "
                     "%.3g times the scatter" % (result.chi2 / result.dof,
                                                 result.dof,
                                                 result.probability, rms))
        lines.append("error bars from the data's scatter (--noise) alone: "
                     + ", ".join(spread(p, v, sd) for p, v, sd in zip(
                         parameters, result.values, result.sigma_scatter)))
        if result.probability < CHI2_PROBABILITY:
            lines.append("warning: the residuals are %.3g times the scatter "
                         "the data allow (--noise): the model does not "
                         "describe the test (a bias its error bars leave "
                         "out), and the values may be off by far more than "
                         "their +-" % rms)
    if result.warnings:
        last = result.warnings.get(result.run_of_fit)
        lines.append("warning: %d of the %d liftoff runs ended `completed "
                     "with warnings`%s: %s"
                     % (len(result.warnings), result.runs,
                        ", the run at the fitted values (%d) too"
                        % result.run_of_fit if last else "",
                        last or next(iter(result.warnings.values()))))
    return lines, error


def publish(output, lines, parameters, result, notes=()):
    """The report's lines, the notes (warnings about the input) and the
    judgement, printed and written to fit.txt; returns the error of a fit
    whose values the data do not fix (None otherwise), for the caller to
    raise once its other files are written."""
    judged, error = judgement(parameters, result)
    text = "\n".join(list(lines) + [n for n in notes if n] + judged) + "\n"
    with open(os.path.join(output, "fit.txt"), "w") as f:
        f.write(text)
    print(text, end="", flush=True)
    return error
