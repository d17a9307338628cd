#!/usr/bin/python3
"""Rainflow counting and Miner's sum (scripts/liftoff_fatigue.py) against
the standard's worked example and a hand calculation.

    fatigue_rainflow.py SCRIPTS_FOLDER

- Rainflow against ASTM E1049-85 (reapproved 2017), "Standard Practices
  for Cycle Counting in Fatigue Analysis", 5.4.4 and its Fig. 6: the
  history -2, 1, -3, 5, -1, 3, -4, 4, -2 (the points A to I) counts, by
  range, the standard's table of Fig. 6(e): range 3: 0.5, 4: 1.5, 6: 0.5,
  8: 1.0, 9: 0.5 (none at 10, 7, 5). The standard's table gives ranges
  and counts; the means and the order below are the steps of 5.4.4 traced
  by hand on Fig. 6: A-B half (range 3, mean -0.5), B-C half (4, -1), E-F
  full (4, 1), C-D half (8, 1), then the residue D-G half (9, 0.5), G-H
  half (8, 0), H-I half (6, 1). The same history sampled finely (points
  between the reversals, repeated values) counts the same.
- Miner's sum under the MEPDG law log10 N = 2.0 (MR / sigma)^1.22, MR =
  4.5 MPa, by hand (a pocket calculator's steps, 6 digits):
  sigma = 4 MPa: (4.5/4)^1.22 = e^(1.22 x 0.117783) = 1.154532, log10 N
  = 2.309065, 1/N = 4.90835e-3; 3 MPa: 1.5^1.22 = e^(1.22 x 0.405465) =
  1.639953, log10 N = 3.279906, 1/N = 5.24922e-4; 2 MPa: 2.25^1.22 =
  e^(1.22 x 0.810930) = 2.689445, log10 N = 5.378890, 1/N = 4.17936e-6.
  A full cycle peaking at 4 MPa, a half at 3, a full at 2 and a full
  cycle peaking in compression (-1 MPa, no damage) sum to 4.90835e-3 +
  0.5 x 5.24922e-4 + 4.17936e-6 = 5.17499e-3.
- The same law as an expression, "2.0*(MR/sigma)^1.22", gives the same
  sum; expressions with anything but numbers, sigma, MR, + - * / ^ and
  the listed functions are refused by name.
- A pass 0 -> 3 MPa -> 0 is two half cycles of range 3 MPa: its damage is
  1/N(3 MPa), as is the damage of its peak alone; a pass that never pulls
  does none.
"""

import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "common"))
from checks import check, finish  # noqa: E402

sys.path.insert(0, sys.argv[1])
import liftoff_fatigue as fatigue  # noqa: E402

ASTM_HISTORY = [-2, 1, -3, 5, -1, 3, -4, 4, -2]
# ASTM E1049-85, Fig. 6(e): counts by range.
ASTM_TABLE = {10: 0, 9: 0.5, 8: 1.0, 7: 0, 6: 0.5, 5: 0, 4: 1.5, 3: 0.5}
# 5.4.4's steps traced by hand on Fig. 6: (range, mean, count).
ASTM_CYCLES = [(3, -0.5, 0.5), (4, -1, 0.5), (4, 1, 1.0), (8, 1, 0.5),
               (9, 0.5, 0.5), (8, 0, 0.5), (6, 1, 0.5)]


def by_range(cycles):
    table = {r: 0.0 for r in ASTM_TABLE}
    for r, _, count in cycles:
        table[r] = table.get(r, 0.0) + count
    return table


def rainflow_checks():
    cycles = fatigue.rainflow(ASTM_HISTORY)
    check(by_range(cycles) == ASTM_TABLE,
          "ASTM E1049 Fig. 6: counts by range %s (standard: %s)"
          % (by_range(cycles), ASTM_TABLE))
    check(cycles == ASTM_CYCLES, "ASTM E1049 Fig. 6: every cycle's range, "
          "mean and count in the order of 5.4.4: %s" % cycles)
    fine = []
    for a, b in zip(ASTM_HISTORY, ASTM_HISTORY[1:]):
        fine += [a + (b - a) * k / 4 for k in range(4)] + [b]
    check(fatigue.rainflow(fine) == ASTM_CYCLES,
          "the history sampled 4 times finer, with repeated values: the "
          "same cycles")
    check(fatigue.rainflow([]) == [] and fatigue.rainflow([1.0]) == [],
          "no cycles in an empty or one-point history")


def miner_checks():
    law = fatigue.Law(4.5e6)
    peaks = [4e6, 3e6, 2e6, -1e6]
    counts = [1.0, 0.5, 1.0, 1.0]
    hand = 5.17499e-3
    d = fatigue.damage(peaks, counts, law)
    check(abs(d - hand) <= 2e-6 * hand,
          "Miner's sum under the MEPDG law: %.6e (hand %.5e)" % (d, hand))
    for peak, inverse in ((4e6, 4.90835e-3), (3e6, 5.24922e-4),
                          (2e6, 4.17936e-6)):
        one = fatigue.damage([peak], [1.0], law)
        check(abs(one - inverse) <= 2e-6 * inverse,
              "1/N(%g Pa) = %.6e (hand %.5e)" % (peak, one, inverse))
    check(fatigue.damage([-1e6, 0.0], [1.0, 1.0], law) == 0.0,
          "cycles that peak in compression or at 0 do no damage")
    expression = fatigue.Law(4.5e6, expression="2.0*(MR/sigma)^1.22")
    e = fatigue.damage(peaks, counts, expression)
    check(abs(e - d) <= 1e-12 * d,
          "the law as the expression 2.0*(MR/sigma)^1.22: %.6e" % e)
    for bad in ("__import__('os').system('true')", "sigma.real",
                "x * sigma", "open('f')", "sigma if 1 else 2", "[sigma]",
                "'text'", "", "2 *"):
        try:
            fatigue.Law(4.5e6, expression=bad)
            check(False, "expression %r refused" % bad)
        except fatigue.LawError as error:
            check("\n" not in str(error),
                  "expression %r refused: %s" % (bad, error))
    for mr in (0, -1.0, float("nan"), "4e6"):
        try:
            fatigue.Law(mr)
            check(False, "MR %r refused" % (mr,))
        except fatigue.LawError as error:
            check(True, "MR %r refused: %s" % (mr, error))


def pass_checks():
    law = fatigue.Law(4.5e6)
    d, peak, single = fatigue.pass_damage([0.0, 1.5e6, 3e6, 1e6, 0.0], law)
    check(abs(d - 5.24922e-4) <= 2e-6 * 5.24922e-4 and peak == 3e6
          and single == d,
          "a pass 0 -> 3 MPa -> 0: damage %.6e, peak %g Pa, its peak alone "
          "%.6e" % (d, peak, single))
    d, peak, single = fatigue.pass_damage([0.0, -2e6, 0.0], law)
    check(d == 0.0 and peak == 0.0 and single == 0.0,
          "a pass that only compresses: no damage, peak tension 0")


rainflow_checks()
miner_checks()
pass_checks()
finish()
