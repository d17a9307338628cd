"""PASS/FAIL lines and the exit code for the Python tests, as test_tools.h
and output_checks.sh give them to the C++ and shell tests."""

import sys

failures = 0


def check(ok, what):
    global failures
    print("%s %s" % ("PASS" if ok else "FAIL", what))
    if not ok:
        failures += 1


def finish():
    print("%d check(s) failed" % failures)
    sys.exit(1 if failures else 0)
