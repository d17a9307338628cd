#!/usr/bin/env python3
"""The figure of doc/studies.md, "A slab lifting off its base": from the
study's runs (doc/base/study.sh), the share of the slab resting on the base
and of the base resting on the subgrade over the truck's pass, and the
force the slab puts on the base.

    /usr/bin/python3 doc/base/figure.py STUDY_OUTPUT FIGURE.png
"""

import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

study, figure = sys.argv[1], sys.argv[2]


def history(name):
    with open(os.path.join(study, name, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


h = history("tensionless")
t = h["t [s]"]
fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
top.plot(t, h["interface_contact_fraction"], label="slab on base")
top.plot(t, h["contact_fraction"], label="base on subgrade")
top.set_ylabel("share in contact")
top.set_ylim(0, 1.05)
top.legend(loc="lower left")
top.set_title("Slab curled at night on a CTB it can lift off, truck at 20 m/s")
bottom.plot(t, [f / 1e3 for f in h["interface_resultant [N]"]],
            label="slab on base")
bottom.set_ylabel("resultant [kN]")
bottom.set_xlabel("t [s]")
bottom.legend(loc="upper left")
fig.tight_layout()
fig.savefig(figure, dpi=110)
