"""Deflectometer sensors' time histories as CSV: the measured histories
scripts/liftoff-backcalc fits, and those of liftoff's runs.

The format (a liftoff history.csv is one as it is):

    t [s],d(0) [um],d(0.305) [um],d(0.61) [um],d(0.914) [um]
    0,0,0,0,0
    0.0005,0.477,0.223,0.059,0.006
    ...

a header, then one row per time. The time is the column named "t [s]", in
seconds from the start of the pulse, strictly increasing. Each sensor is a
column "d(OFFSET) [m]" or "d(OFFSET) [um]": its offset from the load's
centre in m, its deflection (down positive, from the slab at rest before
the pulse, as liftoff's sensors) in m or in micrometres. Other columns
are ignored. Every row has every column, each a finite number.
"""

import csv
import math
import re

import numpy as np

SENSOR = re.compile(r"^d\(([^)]*)\) \[(m|um)\]$")
UNITS = {"m": 1.0, "um": 1e-6}


class HistoryError(Exception):
    """What is wrong with a measured file (histories or a basin), in one
    line."""


def sensor_columns(header, path):
    """[(column index, offset in m, factor to m)] of the sensors."""
    columns = []
    for i, name in enumerate(header):
        match = SENSOR.match(name.strip())
        if name.strip().startswith("d(") and not match:
            raise HistoryError("%s: the column \"%s\" is no sensor column "
                               "d(OFFSET in m) [m or um]" % (path, name))
        if match:
            try:
                offset = float(match.group(1))
            except ValueError:
                raise HistoryError("%s: the column \"%s\" names no offset "
                                   "(d(OFFSET in m) [m or um])"
                                   % (path, name))
            columns.append((i, offset, UNITS[match.group(2)]))
    if not columns:
        raise HistoryError("%s has no sensor column \"d(OFFSET) [m]\" or "
                           "\"d(OFFSET) [um]\"" % path)
    return columns


def read_rows(path):
    """The header and [(line number, row)] of a measured CSV file (a
    basin or histories), every row as long as the header."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise HistoryError("cannot read %s: %s" % (path, e))
    rows = [(line, row) for line, row in enumerate(rows, start=1) if row]
    if len(rows) < 2:
        raise HistoryError("%s holds no rows below its header" % path)
    (_, header), rows = rows[0], rows[1:]
    for line, row in rows:
        if len(row) != len(header):
            raise HistoryError("%s, line %d: %d values, the header names %d"
                               % (path, line, len(row), len(header)))
    return header, rows


def number(text, path, line, name):
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise HistoryError("%s, line %d: %s = \"%s\" is not a finite number"
                           % (path, line, name, text.strip()))
    return value


def read_histories(path):
    """(times in s, sensor offsets in m, deflections in m as an array of
    one row per time, one column per sensor)."""
    header, rows = read_rows(path)
    names = [n.strip() for n in header]
    if "t [s]" not in names:
        raise HistoryError("%s has no time column \"t [s]\"" % path)
    time_column = names.index("t [s]")
    columns = sensor_columns(names, path)
    times, values = [], []
    for line, row in rows:
        times.append(number(row[time_column], path, line, "t [s]"))
        values.append([factor * number(row[i], path, line, names[i])
                       for i, _, factor in columns])
    times = np.array(times)
    steps = np.diff(times)
    if np.any(steps <= 0):
        i = int(np.argmax(steps <= 0)) + 1
        raise HistoryError("%s, line %d: the time %g s does not follow %g s "
                           "(times must increase)"
                           % (path, rows[i][0], times[i], times[i - 1]))
    offsets = np.array([offset for _, offset, _ in columns])
    if len(set(offsets)) != len(offsets):
        raise HistoryError("%s names a sensor offset twice" % path)
    return times, offsets, np.array(values)


def check_window(times, end_time, duration, path):
    """The measured times must lie within the runs' [0, end time] and
    overlap the pulse [0, duration]."""
    if times[0] < 0 or times[-1] > end_time * (1 + 1e-12):
        raise HistoryError("%s spans %g to %g s; the scene's runs cover 0 "
                           "to its End time, %g s" % (path, times[0],
                                                      times[-1], end_time))
    if times[0] >= duration:
        raise HistoryError("%s starts at %g s, after the pulse (0 to %g s): "
                           "there is nothing of the test to fit"
                           % (path, times[0], duration))


def write_histories(path, times, offsets, columns):
    """columns: [(label, deflections in m as times x sensors)]; one column
    per label and sensor, in um."""
    with open(path, "w") as f:
        f.write(",".join(["t [s]"] + ["%s d(%r) [um]" % (label, r)
                                      for label, _ in columns
                                      for r in offsets]) + "\n")
        for i, t in enumerate(times):
            f.write(",".join([repr(float(t))] + [
                "%.6g" % (1e6 * values[i, j]) for _, values in columns
                for j in range(len(offsets))]) + "\n")
