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
"""

import concurrent.futures
import math
import threading

import numpy as np


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

    def __init__(self, run):
        self.run = run
        self.known, self.numbers = {}, {}
        self.lock = threading.Lock()

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


class FitResult:
    def __init__(self, values, sigma, fitted, message, runs):
        self.values, self.sigma, self.fitted = values, sigma, fitted
        self.message, self.runs = message, runs


def describe(parameters, values):
    return ", ".join("%s = %.6g %s" % (p.name, v, p.unit)
                     for p, v in zip(parameters, values))


def fit(parameters, model, measured, scale, tolerance, max_runs,
        sigma_given=None):
    """least_squares of (model(values) - measured) / scale from the
    parameters' starts; model is a RunCache. Prints a line per run."""
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
    try:
        cov = s2 * np.linalg.inv(result.jac.T @ result.jac)
        sigma = [abs(p.derivative(xi)) * math.sqrt(c) for p, xi, c
                 in zip(parameters, result.x, np.diag(cov))]
    except (np.linalg.LinAlgError, ValueError):
        sigma = [math.inf] * len(parameters)
    return FitResult(values, sigma, fitted, result.message, model.runs())
