#!/usr/bin/env python3
"""The speed sweep of the strip of test moving_beam_tensionless
(doc/studies.md, "The strip on a tensionless bed: lift-off against speed"):
the reference's steady state walked up in speed until its branch ends
(the fold), and liftoff's contact ends and w under the load at a few
speeds, in profiles taken every 0.025 of the load's travel from X = -0.1
to 0.25 (after 16 l to 31 l of travel).

    /usr/bin/python3 benchmarks/moving_tensionless_sweep.py build/liftoff \\
        doc/figures/moving-loads [FACTOR]

prints the reference's ends and w under the load against speed, the fold,
and liftoff's ends (mean and range over the profiles) at each speed, and
draws tensionless-ends.png and tensionless-basin.png into the folder.
FACTOR (default 1) multiplies the cells and so divides h and the step
h / (2 v), the patch kept: the figures' discretisation error.
"""

import os
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import scipy.optimize  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests",
                                "common"))
import moving_beam_tensionless as test  # noqa: E402

strip = test.strip
strip.LIFTOFF = sys.argv[1]
folder = sys.argv[2]
factor = int(sys.argv[3]) if len(sys.argv) > 3 else 1
strip.CELLS *= factor
strip.H /= factor
ELL = test.ELL
SPEEDS = (0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.6)
LOAD_AT = tuple(np.round(np.arange(-0.1, 0.2501, 0.025), 3))


def reference_branch():
    """(v/v_cr, a1, a2, b1, b2, w0) along the branch, the fold and the
    solution there."""
    rows, x, r, dr = [], test.STATIC_GUESS, 0.0, 0.01
    while dr > 1e-5:
        beam = test.SteadyLiftoff((r + dr) * strip.V_CR)
        if beam.solve(x):
            r, x = r + dr, beam.x
            rows.append((r, *(x[4:] / ELL), x[0]))
        else:
            dr /= 2
    return np.array(rows), r, x


def upper_branch(start, steps=60):
    """Past the fold: the lifted length ahead a2 - a1 fixed and growing,
    the speed an unknown in its place; rows as reference_branch()."""
    x = start
    lifted = (x[5] - x[4]) / ELL
    u = np.append(test.SteadyLiftoff.pack(x)[[0, 1, 2, 3, 4, 6, 7]],
                  branch[-1, 0])

    def unpack(u):
        x = test.SteadyLiftoff.unpack(np.insert(u[:7], 5, np.log(lifted)))
        return x, u[7]

    def residual(u):
        x, ratio = unpack(u)
        return test.SteadyLiftoff(ratio * strip.V_CR).residual(x)

    rows = []
    for _ in range(steps):
        lifted += 0.1
        result = scipy.optimize.root(residual, u, method="lm",
                                     options={"xtol": 1e-15, "ftol": 1e-15})
        if abs(result.fun).max() > 1e-8:
            break
        u = result.x
        x, ratio = unpack(u)
        rows.append((ratio, *(x[4:] / ELL), x[0]))
    return np.array(rows)


branch, fold, at_fold = reference_branch()
print("reference: one lifted zone on each side up to v/v_cr = %.4f" % fold)
for row in branch[::4]:
    print("  v/v_cr %.3f  a1 %.3f  a2 %.3f  b1 %.3f  b2 %.3f  (l)  w0 %.5e"
          % tuple(row))
upper = upper_branch(at_fold)
print("past the fold (the lifted length ahead fixed, the speed solved for):")
for row in upper[::6]:
    print("  v/v_cr %.3f  a1 %.3f  a2 %.3f  b1 %.3f  b2 %.3f  (l)  w0 %.5e"
          % tuple(row))

measured = []
with tempfile.TemporaryDirectory() as work:
    for ratio in SPEEDS:
        profiles = test.run(ratio, work, LOAD_AT)
        ends = [np.sort(test.sign_changes(s, p)) / ELL
                for s, w, p, under in profiles]
        four = np.array([e for e in ends if len(e) == 4])
        under = np.array([u for s, w, p, u in profiles])
        measured.append((ratio, four, under, profiles))
        print("liftoff at %.2f v_cr: %d of %d profiles with 4 ends" %
              (ratio, len(four), len(ends)))
        if len(four):
            print("  ends mean " + " ".join("%.3f" % e for e in
                                            four.mean(axis=0)) +
                  "  range " + " ".join("%.3f" % e for e in
                                        np.ptp(four, axis=0)))
        print("  w under the load from %.5e to %.5e" % (under.min(),
                                                          under.max()))
        if len(ends) - len(four):
            print("  ends found: " + "; ".join(
                " ".join("%.2f" % e for e in found) for found in ends))

plt.figure(figsize=(6.4, 4.6))
for k, label in enumerate(("b2", "b1", "a1", "a2")):
    column = (4, 3, 1, 2)[k]
    plt.plot(branch[:, 0], branch[:, column], "k-",
             label="reference" if k == 0 else None)
    plt.plot(upper[:, 0], upper[:, column], "k--",
             label="reference past the fold" if k == 0 else None)
    for ratio, four, under, _ in measured:
        if len(four):
            e = four[:, k]
            plt.errorbar(ratio, e.mean(), yerr=[[e.mean() - e.min()],
                                                [e.max() - e.mean()]],
                         fmt="o", color="C0", capsize=3,
                         label="liftoff (mean, range)" if (k, ratio) == (
                             0, SPEEDS[0]) else None)
plt.axvline(fold, color="k", ls=":", label="fold of the reference")
plt.xlabel("v / v_cr")
plt.ylabel("contact ends / l  (behind < 0 < ahead)")
plt.title("lift-off ahead of and behind the load, q = %.2f" % test.WEIGHT)
plt.grid(alpha=0.3)
plt.legend(fontsize=8)
plt.tight_layout()
plt.savefig(os.path.join(folder, "tensionless-ends.png"), dpi=110)

fig, axes = plt.subplots(2, 1, figsize=(6.4, 6), sharex=True)
for axis, ratio in zip(axes, (0.15, 0.3)):
    s = np.linspace(-12 * ELL, 12 * ELL, 481)
    beam = test.reference(ratio)
    axis.plot(s / ELL, beam.profile(s)[:, 0] * 1e6, "k-", label="reference")
    for ratio_, four, under, profiles in measured:
        if ratio_ == ratio:
            for k in (len(profiles) - 5, len(profiles) - 1):
                s_k, w_k = profiles[k][0], profiles[k][1]
                axis.plot(s_k / ELL, w_k * 1e6, "--",
                          label="liftoff, load at X = %.3f" % LOAD_AT[k])
    axis.axhline(0, color="grey", lw=0.5)
    axis.set_xlim(-12, 12)
    axis.set_ylabel("w * 1e6")
    axis.set_title("v = %.2f v_cr" % ratio)
    axis.legend(fontsize=8)
    axis.grid(alpha=0.3)
axes[-1].set_xlabel("s / l (ahead of the load > 0)")
plt.tight_layout()
plt.savefig(os.path.join(folder, "tensionless-basin.png"), dpi=110)
print("wrote tensionless-ends.png and tensionless-basin.png in", folder)
