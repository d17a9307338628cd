#!/usr/bin/python3
"""The largest difference between two CSV files that liftoff wrote, column
by column, relative to the column's largest magnitude in the first file:
what benchmarks/same_results.sh accepts where the files are not
byte-identical (a change that makes liftoff faster may move results in
their last bits, issue 67).

    column_difference.py OLD.csv NEW.csv TOLERANCE

Prints "largest D in COLUMN" and exits 0 if every column differs by at
most TOLERANCE times its largest magnitude, 1 otherwise (also if the
headers or the numbers of rows differ, or a value is not a number in one
file only; an empty cell counts as not a number).
"""

import csv
import math
import sys


def number(text):
    """A cell's value; an empty cell (a quantity not defined at that step,
    as a joint's LTE with no load near it) as NaN, so that two files empty
    at the same cells agree there."""
    return float(text) if text != "" else math.nan


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[number(v) for v in row] for row in rows[1:]]


def main():
    old_path, new_path, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])
    (old_header, old), (new_header, new) = read(old_path), read(new_path)
    if old_header != new_header or len(old) != len(new):
        print("headers or row counts differ")
        return 1
    worst, worst_column = 0.0, old_header[0]
    for j, column in enumerate(old_header):
        scale = max((abs(row[j]) for row in old if math.isfinite(row[j])),
                    default=0.0)
        for a, b in zip((row[j] for row in old), (row[j] for row in new)):
            if math.isnan(a) and math.isnan(b):
                continue
            if a == b:
                continue
            if not (math.isfinite(a) and math.isfinite(b)):
                print("%s: %r against %r" % (column, a, b))
                return 1
            relative = abs(a - b) / scale if scale > 0 else math.inf
            if relative > worst:
                worst, worst_column = relative, column
    print("largest %.2g in %s" % (worst, worst_column))
    return 0 if worst <= tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
