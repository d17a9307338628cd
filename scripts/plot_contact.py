#!/usr/bin/python3
"""The contact status and the deflection of runs at their last field file,
side by side on the full plate (matplotlib, Agg):

    scripts/plot_contact.py night-run day-run --titles "night" "day" \\
        --output curling.png

Each panel: the region in contact with the bed (grey) and the region
lifted off (white), with contours of w; a half or quarter model is
mirrored into the full plate. Coordinates and w in the scene's units (m
in an SI scene, where w is drawn in mm).
"""

import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liftoff_runs import used_parameters  # noqa: E402


def last_fields(run):
    """Points, w and contact status of the last time's field files of
    `run` (every rank's piece), mirrored into the full plate."""
    import meshio
    files = sorted(glob.glob(os.path.join(run, "solution_*.vtu")))
    if not files:
        sys.exit(f"plot_contact.py: error: {run} has no field files "
                 "(solution_*.vtu; was Output/VTU interval 0?)")
    last = os.path.basename(files[-1]).split(".")[0]
    pieces = [meshio.read(f) for f in files if os.path.basename(f).startswith(last)]
    x = np.concatenate([m.points[:, 0] for m in pieces])
    y = np.concatenate([m.points[:, 1] for m in pieces])
    w = np.concatenate([m.point_data["w"] for m in pieces])
    status = np.concatenate([m.point_data["contact_status"] for m in pieces])
    symmetry = used_parameters(run).get("Discretization/Symmetry", "full")
    mirrors = {"full": [(1, 1)], "half": [(1, 1), (-1, 1)],
               "quarter": [(1, 1), (-1, 1), (1, -1), (-1, -1)]}[symmetry]
    return (np.concatenate([sx * x for sx, _ in mirrors]),
            np.concatenate([sy * y for _, sy in mirrors]),
            np.tile(w, len(mirrors)), np.tile(status, len(mirrors)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="output folders of runs")
    parser.add_argument("--titles", nargs="*", default=[])
    parser.add_argument("--output", default="contact.png")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, len(args.runs), squeeze=False,
                                figsize=(5.5 * len(args.runs), 4.2))
    for k, run in enumerate(args.runs):
        x, y, w, status = last_fields(run)
        si = used_parameters(run).get("Units/System", "dimensionless") == "SI"
        scale, unit = (1e3, "mm") if si else (1, "")
        axis = axes[0][k]
        axis.tricontourf(x, y, status, levels=[-0.5, 0.5, 1.5],
                         colors=["white", "0.75"])
        lines = axis.tricontour(x, y, scale * w, levels=10, colors="k",
                                linewidths=0.7)
        axis.clabel(lines, fontsize=7, fmt="%.2f")
        axis.set_aspect("equal")
        title = args.titles[k] if k < len(args.titles) else run
        axis.set_title(f"{title}: grey in contact, w [{unit}]" if si
                       else f"{title}: grey in contact, w")
        axis.set_xlabel("x [m]" if si else "x")
        axis.set_ylabel("y [m]" if si else "y")
    figure.tight_layout()
    figure.savefig(args.output, dpi=110)
    print(f"plot_contact.py: wrote {args.output}")


if __name__ == "__main__":
    main()
