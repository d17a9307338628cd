"""A study's quantities of interest: a column of a run's history.csv or
its profiles, sampled at given times, or a column's peak over the run's own
steps, and the relative max-norm difference between two runs' values. Shared by scripts/liftoff-study's full ladder and
its target-driven climb (scripts/liftoff_target.py).
"""

import numpy as np


class StudyError(Exception):
    pass


def tolerance(times):
    return 1e-9 * np.maximum(1.0, np.abs(times))


def sample(taus, values, times):
    """values(tau) at the given times: the stored value where a time is one
    of taus, else linear interpolation between the neighbours."""
    taus, values = np.asarray(taus), np.asarray(values)
    times = np.asarray(times, dtype=float)
    tol = tolerance(times)
    k = np.searchsorted(taus, times - tol)
    inside = k < len(taus)
    exact = inside & (np.abs(taus[np.minimum(k, len(taus) - 1)] - times)
                      <= tol)
    between = inside & (k > 0)
    outside = ~(exact | between)
    if outside.any():
        raise StudyError("time %g is outside a run's history"
                         % times[outside][0])
    out = np.interp(times, taus, values)
    out[exact] = values[k[exact]]
    return out


def split_qoi(qoi):
    """"name@T" as (name, T); "name" as (name, None). A riding probe's
    column has an '@' of its own ("w@patch_load_1"): only a number after
    the last '@' is a start time."""
    name, at, start = qoi.rpartition("@")
    if not at:
        return qoi, None
    try:
        return name, float(start)
    except ValueError:
        if "@" in name:
            raise StudyError("--qoi '%s': the start time after the last '@' "
                             "must be a number" % qoi)
        return qoi, None


PEAK = "peak:"


def is_peak(qoi):
    return qoi.startswith(PEAK)


def peak(run, qoi, times):
    """"peak:name" as (value, time): the value of largest magnitude, with
    its sign, over the run's own history rows from the first to the last
    of times. Sampled at a coarser run's times instead, a peak between
    them would be cut off by an amount that depends on where the coarse
    steps fall, not on the run's error."""
    name = qoi[len(PEAK):]
    history = run["history"]
    if name not in history.columns:
        raise StudyError("quantity of interest '%s' is not a column of "
                         "history.csv; the columns are: %s"
                         % (name, ", ".join(history.columns)))
    taus = history["tau"].to_numpy()
    keep = ((taus >= times[0] - tolerance(times[0]))
            & (taus <= times[-1] + tolerance(times[-1])))
    taus, values = taus[keep], history[name].to_numpy()[keep]
    if np.all(np.isnan(values)):
        raise StudyError("'%s' is empty in every row of run %s (a load "
                         "transfer whose load stays far from its joint)"
                         % (name, run["label"]))
    k = int(np.nanargmax(np.abs(values)))
    return float(values[k]), float(taus[k])


def qoi_values(run, qoi, times):
    """The quantity as one array, comparable between runs. "name@T" is the
    quantity from tau = T on; "peak:name" is a one-value array."""
    qoi, start = split_qoi(qoi)
    times = np.asarray(times)
    if start is not None:
        times = times[times >= start - tolerance(start)]
        if not len(times):
            raise StudyError("'%s@%g' starts after the end time" % (qoi,
                                                                   start))
    if is_peak(qoi):
        return np.array([peak(run, qoi, times)[0]])
    if qoi == "profiles":
        profiles = run["profiles"]
        if profiles is None or profiles.empty:
            raise StudyError("'profiles' asked for, but run %s wrote no "
                             "profiles.csv (set Output/Profile points and "
                             "Profile times)" % run["label"])
        return profiles["w"].to_numpy()[
            profiles["tau"].to_numpy() >= times[0] - tolerance(times[0])]
    history = run["history"]
    if qoi not in history.columns:
        raise StudyError("quantity of interest '%s' is not a column of "
                         "history.csv; the columns are: %s"
                         % (qoi, ", ".join(history.columns)))
    return sample(history["tau"].to_numpy(), history[qoi].to_numpy(), times)


def difference(a, b, scale):
    if len(a) != len(b):
        raise StudyError("quantities of different length (%d, %d): do the "
                         "runs write the same profiles?" % (len(a), len(b)))
    # An empty cell (a load transfer with the load far from its joint) is
    # compared where both runs have a value.
    both = ~(np.isnan(a) | np.isnan(b))
    if not np.any(both):
        raise StudyError("no row where both runs give the quantity (empty "
                         "cells: a load transfer with the load far)")
    return float(np.max(np.abs(a[both] - b[both]))) / scale


def magnitude(values):
    """The largest magnitude, or 1 where all are zero (a relative error
    then is an absolute one)."""
    return float(np.nanmax(np.abs(values), initial=0.0)) or 1.0
