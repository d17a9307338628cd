#!/usr/bin/env python3
"""The pictures of doc/tutorial.md, from the runs' own files:

    /usr/bin/python3 scripts/tutorial_figures.py first-slab \\
        output-tutorial-1-first-slab doc/figures/tutorial-1-first-slab.png
    /usr/bin/python3 scripts/tutorial_figures.py jointed-truck \\
        output-tutorial-2-jointed-truck \\
        doc/figures/tutorial-2-jointed-truck.png
    /usr/bin/python3 scripts/tutorial_figures.py study \\
        study-tutorial-4 doc/figures/tutorial-4-study.png
    /usr/bin/python3 scripts/tutorial_figures.py engineer \\
        output-engineer-history doc/figures/pavement-engineer.png

first-slab and jointed-truck read history.csv and profiles.csv of a run,
study reads study.csv of scripts/liftoff-study, engineer history.csv of
prm/pavement-engineer.prm run with Output/Write stress history = true
(each face's largest principal stress per step, in Pa). Each also prints the
numbers the tutorial quotes. Stresses are 6 M / H^2 of the moments liftoff
writes (N m/m), with H the scene's thickness (read from used_parameters.prm).
"""

import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liftoff_runs import used_parameters  # noqa: E402


def thickness(run):
    return float(used_parameters(run)["Units/Thickness"])


def peak(history, column):
    """The row where |column| is largest."""
    return history.loc[history[column].abs().idxmax()]


def first_slab(run, figure):
    h = pandas.read_csv(os.path.join(run, "history.csv"))
    p = pandas.read_csv(os.path.join(run, "profiles.csv"))
    stress = 6 / thickness(run) ** 2
    t = h["t [s]"] * 1e3
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    ax[0].plot(t, h["w(0;2.25) [m]"] * 1e3, label="under the wheel (0, 2.25)")
    ax[0].plot(t, h["w(0;-2.5) [m]"] * 1e3, label="far edge (0, -2.5)")
    ax[0].plot(t, h["w(2.5;2.5) [m]"] * 1e3, label="corner (2.5, 2.5)")
    ax[0].set_ylabel("w [mm] (down positive)")
    twin = ax[0].twinx()
    twin.plot(t, h["contact_fraction"], "k:", label="contact fraction")
    twin.set_ylabel("contact fraction")
    ax[0].legend(fontsize=7, loc="upper right")
    twin.legend(fontsize=7, loc="lower right")
    ax[1].plot(t, h["sigma_xx(0;2.25) [Pa]"] * 1e-6,
               label="sigma_xx under the wheel, bottom")
    ax[1].plot(t, h["sigma_yy(0;2.25) [Pa]"] * 1e-6,
               label="sigma_yy under the wheel, bottom")
    ax[1].plot(t, h["max_M_1 [N m/m]"] * stress * 1e-6, "--",
               label="6 max_M_1 / H^2 (largest, bottom)")
    ax[1].plot(t, -h["min_M_2 [N m/m]"] * stress * 1e-6, "--",
               label="-6 min_M_2 / H^2 (largest, top)")
    ax[1].set_ylabel("bending stress [MPa]")
    ax[1].legend(fontsize=7)
    for time, profile in p.groupby("t [s]"):
        ax[2].plot(profile["y [m]"], profile["w [m]"] * 1e3,
                   label="t = %g ms" % (time * 1e3))
    ax[2].axhline(0, color="k", lw=0.5)
    ax[2].set_xlabel("y [m] along x = 0 (the wheel at y = 2.25)")
    ax[2].set_ylabel("w [mm]")
    ax[2].legend(fontsize=7)
    for a in ax[:2]:
        a.set_xlabel("t [ms]")
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle("Tutorial step 1: 50 kN wheel pulse on a 5 m slab "
                 "(prm/tutorial-1-first-slab.prm)")
    fig.tight_layout()
    fig.savefig(figure, dpi=100)
    for column in ("w(0;2.25) [m]", "sigma_xx(0;2.25) [Pa]",
                   "max_M_1 [N m/m]", "max_uplift [m]", "max_pressure [Pa]"):
        row = peak(h, column)
        print("%s: largest %.6g at t = %g s" % (column, row[column],
                                                 row["t [s]"]))
    row = peak(h, "max_M_1 [N m/m]")
    print("largest bottom tension 6 max_M_1 / H^2 = %.4g MPa at (%g, %g) m"
          % (row["max_M_1 [N m/m]"] * stress * 1e-6, row["max_M_1_x [m]"],
             row["max_M_1_y [m]"]))
    print("smallest contact fraction %.4f at t = %g s" % (
        h["contact_fraction"].min(),
        h["t [s]"][h["contact_fraction"].idxmin()]))
    print("resultant at t = 0: %.6g N" % h["resultant [N]"][0])


def jointed_truck(run, figure):
    h = pandas.read_csv(os.path.join(run, "history.csv"))
    p = pandas.read_csv(os.path.join(run, "profiles.csv"))
    stress = 6 / thickness(run) ** 2
    t = h["t [s]"]
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    ax[0].plot(t, h["max_M_1 [N m/m]"] * stress * 1e-6,
               label="largest bottom tension, 6 max_M_1 / H^2")
    ax[0].plot(t, -h["min_M_2 [N m/m]"] * stress * 1e-6,
               label="largest top tension, -6 min_M_2 / H^2")
    ax[0].set_ylabel("stress [MPa]")
    ax[0].set_xlabel("t [s]")
    ax[0].legend(fontsize=7)
    dowels = [c for c in h.columns if c.startswith("dowel_x1_")]
    for c in dowels[:3]:
        ax[1].plot(t, h[c] * 1e-3, label=c.replace(" [N]", ""))
    ax[1].plot(t, h["shear_x1 [N]"] * 1e-3, "k--",
               label="shear_x1 (aggregate interlock)")
    ax[1].set_ylabel("force [kN]")
    ax[1].set_xlabel("t [s] (the rear axle crosses x1 at 0.16 s)")
    ax[1].legend(fontsize=7)
    for time, profile in p.groupby("t [s]"):
        ax[2].plot(profile["x [m]"], profile["w [m]"] * 1e3,
                   label="t = %g s" % time)
    for joint in (-2.25, 2.25):
        ax[2].axvline(joint, color="grey", lw=0.5)
    ax[2].axhline(0, color="k", lw=0.5)
    ax[2].set_xlabel("x [m] along y = -1.6 (outer wheels; joints grey)")
    ax[2].set_ylabel("w [mm] (negative: above the bed's level)")
    ax[2].legend(fontsize=7)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle("Tutorial step 2: truck on three doweled slabs curled at "
                 "night (prm/tutorial-2-jointed-truck.prm)")
    fig.tight_layout()
    fig.savefig(figure, dpi=100)
    for column, sign, face in (("max_M_1", 1, "bottom"),
                               ("min_M_2", -1, "top")):
        row = peak(h, column + " [N m/m]")
        print("largest %s tension %.4g MPa at (%g, %g) m, t = %g s "
              "(front axle at x = %g m); at t = 0: %.4g MPa" % (
                  face, sign * row[column + " [N m/m]"] * stress * 1e-6,
                  row[column + "_x [m]"], row[column + "_y [m]"],
                  row["t [s]"], row["vehicle_1_x [m]"],
                  sign * h[column + " [N m/m]"][0] * stress * 1e-6))
    print("contact fraction at t = 0: %.4f, smallest %.4f" % (
        h["contact_fraction"][0], h["contact_fraction"].min()))
    print("largest uplift at t = 0: %.4g mm" % (h["max_uplift [m]"][0] * 1e3))
    forces = h[[c for c in h.columns if c.startswith("dowel_")]].abs()
    name = forces.max().idxmax()
    print("largest dowel force %.4g N (%s) at t = %g s" % (
        forces[name].max(), name, t[forces[name].idxmax()]))
    for joint in ("x1", "x2"):
        lte = h["lte_" + joint].dropna()
        print("lte_%s: %.3f to %.3f" % (joint, lte.min(), lte.max()))


def study(folder, figure):
    s = pandas.read_csv(os.path.join(folder, "study.csv"))
    runs = s[s["run"].str.match(r"c\d+$")]
    thickness_ = 0.25  # the tutorial slab's, prm/si-concrete-slab-pulse.prm
    value = runs["value:peak:max_M_1 [N m/m]"] * 6 / thickness_**2 * 1e-6
    # Cells along x = cells along y; the half model's cells count both.
    along = runs["cells"] ** 0.5
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    ax[0].plot(along, value, "o-")
    ax[0].set_xscale("log", base=2)
    ax[0].set_xlabel("cells along x and y (Q2, the half x >= 0, "
                     "2.5 m x 5 m)")
    ax[0].set_ylabel("largest bottom tension over the pulse [MPa]")
    ax[1].loglog(runs["process_wall"][:-1],
                 runs["error:peak:max_M_1 [N m/m]"][:-1], "o-",
                 label="largest tension (max_M_1)")
    ax[1].loglog(runs["process_wall"][:-1],
                 runs["error:peak:sigma_xx(0;2.25) [Pa]"][:-1], "s-",
                 label="sigma_xx under the wheel")
    ax[1].loglog(runs["process_wall"][:-1],
                 runs["error:peak:w(0;2.25) [m]"][:-1], "^-",
                 label="w under the wheel")
    ax[1].axhline(0.01, color="grey", lw=0.5)
    ax[1].set_xlabel("cost: wall time of the run [s]")
    ax[1].set_ylabel("peak's error against the finest run")
    ax[1].legend(fontsize=7)
    for a in ax:
        a.grid(alpha=0.3, which="both")
    fig.suptitle("Tutorial step 4: the largest stress over 8 to 128 cells "
                 "(prm/tutorial-4-study.prm)")
    fig.tight_layout()
    fig.savefig(figure, dpi=100)
    for (_, row), sigma in zip(runs.iterrows(), value):
        print("%s: %d dofs, largest tension %.4f MPa, error %.2g, %.2f s" % (
            row["run"], row["dofs"], sigma,
            row["error:peak:max_M_1 [N m/m]"], row["process_wall"]))


def engineer(run, figure):
    """Each face's largest tension per step and where it lies along x,
    beside the truck's axles (the steering axle on the path's point, the
    tandem's two 5 m behind it, 1.3 m apart) and the joints."""
    h = pandas.read_csv(os.path.join(run, "history.csv"))
    t = h["t [s]"]
    fig, ax = plt.subplots(1, 2, figsize=(11, 3.8))
    for face, style in (("top", "-"), ("bottom", "--")):
        column = "max_sigma_1_%s [Pa]" % face
        ax[0].plot(t, h[column] * 1e-6, style, label="%s face" % face)
        ax[1].plot(t, h["max_sigma_1_%s_x [m]" % face], style,
                   label="largest tension, %s face" % face)
        row = peak(h, column)
        print("largest tension %.3g MPa, %s face, slab %d, at (%.3g, %.3g) m,"
              " t = %g s; at t = 0: %.3g MPa" % (
                  row[column] * 1e-6, face,
                  row["max_sigma_1_%s_slab" % face],
                  row["max_sigma_1_%s_x [m]" % face],
                  row["max_sigma_1_%s_y [m]" % face], row["t [s]"],
                  h[column][0] * 1e-6))
    ax[0].set_ylabel("largest principal stress [MPa]")
    ax[0].set_xlabel("t [s]")
    ax[0].legend(fontsize=7)
    front = h["vehicle_1_x [m]"]
    for offset, label in ((0, "steering axle"), (-4.35, "tandem's axles"),
                          (-5.65, None)):
        ax[1].plot(t, front + offset, ":", color="grey", label=label)
    for joint in (-2.75, 2.75):
        ax[1].axhline(joint, color="k", lw=0.5)
    ax[1].set_ylim(-7.25, 7.25)
    ax[1].set_xlabel("t [s]")
    ax[1].set_ylabel("x [m] (joints at -2.75 and 2.75 m)")
    ax[1].legend(fontsize=7)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle("The engineer's scene: the largest tension of each face and "
                 "where it lies (prm/pavement-engineer.prm)")
    fig.tight_layout()
    fig.savefig(figure, dpi=100)


if __name__ == "__main__":
    modes = {"first-slab": first_slab, "jointed-truck": jointed_truck,
             "study": study, "engineer": engineer}
    if len(sys.argv) != 4 or sys.argv[1] not in modes:
        sys.exit(__doc__)
    modes[sys.argv[1]](sys.argv[2], sys.argv[3])
