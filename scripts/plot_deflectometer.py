#!/usr/bin/python3
"""The peak basins and the sensors' histories of deflectometer runs, one
picture (matplotlib, Agg):

    scripts/plot_deflectometer.py output-fwd-centre output-fwd-edge \\
        output-fwd-corner --output fwd.png

Left: each run's basin.csv (peak deflection against the sensor's offset);
right: the first run's history.csv, the deflection at each sensor against
time. Runs of SI scenes (offsets in m, deflections in m, t in s).
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liftoff_runs import read_csv  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="output folders of runs")
    parser.add_argument("--output", default="deflectometer.png")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, (basin, history) = plt.subplots(1, 2, figsize=(11, 4))
    for run in args.runs:
        rows = read_csv(os.path.join(run, "basin.csv"))
        basin.plot([1e3 * r["offset [m]"] for r in rows],
                   [-1e6 * r["peak_w [m]"] for r in rows], "o-",
                   label=os.path.basename(os.path.normpath(run)))
    basin.set_xlabel("sensor offset from the load [mm]")
    basin.set_ylabel("peak deflection [um] (down)")
    basin.set_title("peak basins")
    basin.legend()
    rows = read_csv(os.path.join(args.runs[0], "history.csv"))
    for name in rows[0]:
        if name.startswith("d("):
            history.plot([1e3 * r["t [s]"] for r in rows],
                         [-1e6 * r[name] for r in rows], label=name)
    history.set_xlabel("t [ms]")
    history.set_ylabel("deflection [um] (down)")
    history.set_title("sensors of " + os.path.basename(
        os.path.normpath(args.runs[0])))
    history.legend(fontsize=7)
    for axes in (basin, history):
        axes.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(args.output, dpi=110)


if __name__ == "__main__":
    main()
