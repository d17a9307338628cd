#!/usr/bin/python3
"""Plot w at a probe of Example 3 for Newmark and generalized-alpha runs,
and their difference from a reference run with a smaller step whose
recorded times include theirs (see doc/stability.md).

    /usr/bin/python3 scripts/plot_generalized_alpha.py OUT.png LABEL=history.csv ...

The first history is the reference (drawn black); the column plotted is
w(0.15;0).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

COLUMN = "w(0.15;0)"


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [float(r["tau"]) for r in rows], [float(r[COLUMN]) for r in rows]


def main():
    out, runs = sys.argv[1], [a.rsplit("=", 1) for a in sys.argv[2:]]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    reference = dict(zip(*[[round(t, 9) for t in read(runs[0][1])[0]],
                           read(runs[0][1])[1]]))
    for i, (label, path) in enumerate(runs):
        tau, w = read(path)
        style = dict(color="black", lw=2.0) if i == 0 else dict(lw=1.0)
        axes[0].plot(tau, w, label=label, **style)
        if i > 0:
            axes[1].plot(tau, [x - reference[round(t, 9)]
                               for t, x in zip(tau, w)], label=label, lw=1.0)
    axes[0].set_ylabel("v at (0.15, 0)")
    axes[1].set_ylabel("difference from the reference")
    for ax in axes:
        ax.set_xlabel("tau")
        ax.grid(alpha=0.3)
    axes[0].set_title("Example 3: deflection")
    axes[1].set_title("error against the reference")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
