#!/usr/bin/env python3
"""The picture of both layers of prm/base-curled-slab-truck.prm: w of the
slab and of the base along one line of the slab, settled at night before
the truck and at a later time, with the gap between them.

    /usr/bin/python3 doc/base/profiles.py OUTPUT Y STEP FIGURE.png

OUTPUT the scene's folder run with VTU files (Output/VTU interval), Y the
line y = Y [m], STEP a step whose VTU file exists.
"""

import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

folder, line, step, figure = sys.argv[1], float(sys.argv[2]), \
    int(sys.argv[3]), sys.argv[4]


def along(step):
    mesh = meshio.read(os.path.join(folder, f"solution_{step:05d}.0000.vtu"))
    x, y = mesh.points[:, 0], mesh.points[:, 1]
    on = np.abs(y - line) < 1e-6
    order = np.argsort(x[on])
    fields = mesh.point_data
    return (x[on][order], 1e3 * fields["w"][on][order],
            1e3 * fields["w_base"][on][order])


fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
for ax, s, title in zip(axes, (0, step), ("settled at night, before the truck",
                                          f"step {step}")):
    x, w, w_base = along(s)
    ax.plot(x, w, label="slab w")
    ax.plot(x, w_base, label="base w")
    ax.fill_between(x, w, w_base, where=w_base > w, color="tab:red",
                    alpha=0.3, label="gap (slab off the base)")
    ax.invert_yaxis()
    ax.set_ylabel("w [mm] (down)")
    ax.set_title(f"y = {line} m, {title}")
    ax.legend(loc="lower center", fontsize=8)
axes[-1].set_xlabel("x [m]")
fig.tight_layout()
fig.savefig(figure, dpi=110)
