#!/usr/bin/python3
"""Run the four examples of Ascione, Bruno & Olivito (1984) with every
variant doc/examples.md shows, plot them into doc/figures/ and print the
active-set iterations and run times.

    /usr/bin/python3 scripts/examples.py [--only 1,2,3,4] [--plot-only]
                                         [--build build] [--output examples-output]

Each variant is a scene of prm/ with overrides (scripts/liftoff_runs.py),
run in its own process into OUTPUT/<variant>/; mesh, degree, time step and
integration variants are never copies of scene files. --plot-only redraws
from the CSV files of an earlier run.
"""
import argparse
import os
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liftoff_runs import parse_summary, read_csv, run_scene, scene_with_overrides  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIGURES = os.path.join(ROOT, "doc", "figures")

BEAM = "prm/example-1-beam.prm"
PLATE = "prm/example-3-square-plate.prm"
SUPPORTED = "prm/example-4-simply-supported-plate.prm"

# (example, variant name, scene, overrides, label in the plots)
VARIANTS = [
    (1, "ex1-q1-20", BEAM, ["Discretization/Cells along x=20"], "20 Q1"),
    (1, "ex1-q1-40", BEAM, [], "40 Q1"),
    (1, "ex1-q1-60", BEAM, ["Discretization/Cells along x=60"], "60 Q1"),
    (1, "ex1-q2-20", BEAM, ["Discretization/Cells along x=20",
                            "Discretization/Polynomial degree=2"], "20 Q2"),
    # The paper's 20 eight-node elements (its Fig. 3d).
    (1, "ex1-s2-20", BEAM, ["Discretization/Cells along x=20",
                            "Discretization/Polynomial degree=2",
                            "Discretization/Element=serendipity"], "20 S2"),
    (1, "ex1-dt-0.025e-2", BEAM, ["Time integration/Time step=2.5e-4"],
     "dtau = 0.025e-2"),
    (1, "ex1-dt-0.2e-2", BEAM, ["Time integration/Time step=2e-3"],
     "dtau = 0.2e-2"),
    (1, "ex1-dt-0.5e-2", BEAM, ["Time integration/Time step=5e-3"],
     "dtau = 0.5e-2"),
    # The paper's L read as the half length: mu, Delta and Gamma in liftoff's
    # units (L = full length) become mu/2, Delta/2, 16 Gamma, the paper's
    # tau' = 4 tau, xi' = 2 xi and v' = 4 v; its dtau' = 0.05e-2 and
    # tau' <= 0.2 are dtau = 1.25e-4 and tau <= 0.05 here.
    (1, "ex1-L-half", BEAM, ["Plate/Aspect ratio=0.025",
                             "Plate/Thickness ratio=0.025",
                             "Foundation/Stiffness=16",
                             "Time integration/Time step=1.25e-4",
                             "Time integration/End time=0.05",
                             "Output/Probe points=0, 0; 0.075, 0",
                             "Output/Profile times=0.0025, 0.0125, 0.025, "
                             "0.05"], "L read as the half length"),
    (2, "ex2-ramp", "prm/example-2-beam-ramp.prm", [], "ramp"),
    (2, "ex2-pulse", "prm/example-2-beam-pulse.prm", [], "pulse"),
    (3, "ex3-q1-8", PLATE, ["Discretization/Cells along x=8",
                            "Discretization/Cells along y=8",
                            "Discretization/Polynomial degree=1"], "8x8 Q1"),
    (3, "ex3-q1-16", PLATE, ["Discretization/Polynomial degree=1"],
     "16x16 Q1"),
    (3, "ex3-q1-32", PLATE, ["Discretization/Cells along x=32",
                             "Discretization/Cells along y=32",
                             "Discretization/Polynomial degree=1"],
     "32x32 Q1"),
    (3, "ex3-q2-8", PLATE, ["Discretization/Cells along x=8",
                            "Discretization/Cells along y=8"], "8x8 Q2"),
    (3, "ex3-q2-16", PLATE, [], "16x16 Q2"),
    # The paper's eight-node element (serendipity), full integration as the
    # paper used for Example 3, and reduced integration for comparison.
    (3, "ex3-s2-8", PLATE, ["Discretization/Cells along x=8",
                            "Discretization/Cells along y=8",
                            "Discretization/Element=serendipity"], "8x8 S2"),
    (3, "ex3-s2-16", PLATE, ["Discretization/Element=serendipity"],
     "16x16 S2"),
    (3, "ex3-s2-8-reduced", PLATE, ["Discretization/Cells along x=8",
                                    "Discretization/Cells along y=8",
                                    "Discretization/Element=serendipity",
                                    "Discretization/Shear integration=reduced"],
     "8x8 S2, reduced"),
    (4, "ex4-reduced", SUPPORTED, [], "15x15 Q1, reduced"),
    (4, "ex4-full", SUPPORTED, ["Discretization/Shear integration=full"],
     "15x15 Q1, full"),
    (4, "ex4-mitc", SUPPORTED, ["Discretization/Shear integration=mitc"],
     "15x15 Q1, MITC"),
    (4, "ex4-reference", SUPPORTED, ["Discretization/Cells along x=30",
                                     "Discretization/Cells along y=30",
                                     "Discretization/Polynomial degree=2",
                                     "Discretization/Shear integration=mitc"],
     "30x30 Q2, MITC (reference)"),
    # Eight- and nine-node elements on the paper's 15 x 15 mesh, reduced
    # integration as the paper used; the eight-node element fully
    # integrated; and 8 x 8 eight-node cells, about the unknowns of 15 x 15
    # Q1.
    (4, "ex4-s2-15-reduced", SUPPORTED, ["Discretization/Polynomial degree=2",
                                         "Discretization/Element=serendipity"],
     "15x15 S2, reduced"),
    (4, "ex4-q2-15-reduced", SUPPORTED, ["Discretization/Polynomial degree=2"],
     "15x15 Q2, reduced"),
    (4, "ex4-s2-15-full", SUPPORTED, ["Discretization/Polynomial degree=2",
                                      "Discretization/Element=serendipity",
                                      "Discretization/Shear integration=full"],
     "15x15 S2, full"),
    (4, "ex4-s2-8-reduced", SUPPORTED, ["Discretization/Cells along x=8",
                                        "Discretization/Cells along y=8",
                                        "Discretization/Polynomial degree=2",
                                        "Discretization/Element=serendipity"],
     "8x8 S2, reduced"),
]


def run(variants, build, output):
    for example, name, scene, overrides, _ in variants:
        directory = os.path.join(output, name)
        text = scene_with_overrides(os.path.join(ROOT, scene),
                                    overrides + ["Output/VTU interval=0"],
                                    directory)
        start = time.time()
        run_scene(os.path.join(build, "liftoff"), text, directory)
        print("ran %-16s %6.1f s" % (name, time.time() - start), flush=True)


def history(output, name):
    return read_csv(os.path.join(output, name, "history.csv"))


def profiles(output, name):
    """profiles.csv as {tau: (x, w)}."""
    result = {}
    for row in read_csv(os.path.join(output, name, "profiles.csv")):
        xs, ws = result.setdefault(round(row["tau"], 9), ([], []))
        xs.append(row["x"])
        ws.append(row["w"])
    return result


def column(rows, key):
    return [r[key] for r in rows]


def draw_profiles(ax, output, name, title):
    for tau, (x, w) in sorted(profiles(output, name).items()):
        ax.plot(x, w, label="tau = %g" % tau)
    ax.axhline(0, color="grey", lw=0.6)
    ax.set_xlabel("xi")
    ax.set_ylabel("v")
    ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)


def save(fig, name):
    fig.tight_layout()
    path = os.path.join(FIGURES, name)
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print("wrote", os.path.relpath(path, ROOT))


def label_of(name):
    return next(v[4] for v in VARIANTS if v[1] == name)


def plot_example_1(output):
    meshes = ["ex1-q1-20", "ex1-q1-40", "ex1-q1-60", "ex1-q2-20"]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharey=True)
    for ax, name in zip(axes.flat, meshes):
        draw_profiles(ax, output, name, "Example 1, v along the axis, "
                      + label_of(name) + " (half beam)")
    save(fig, "example-1-profiles.png")

    # The first instants, when the beam lifts off beyond the load, and the
    # same beam with L read as the half length, in the paper's units.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for tau, (x, w) in sorted(profiles(output, "ex1-q1-40").items()):
        if tau <= 0.02:
            axes[0].plot(x, w, label="tau = %g" % tau)
    axes[0].set_title("Example 1, 40 Q1 (L = full length): first instants",
                      fontsize=10)
    axes[0].set_xlabel("xi")
    axes[0].set_ylabel("v")
    for tau, (x, w) in sorted(profiles(output, "ex1-L-half").items()):
        axes[1].plot([2 * a for a in x], [4 * b for b in w],
                     label="paper's tau = %g" % (4 * tau))
    axes[1].set_title("40 Q1, L read as the half length (paper's xi, tau, "
                      "v)", fontsize=10)
    axes[1].set_xlabel("xi (paper's, 0 to 1)")
    axes[1].set_ylabel("v (paper's)")
    for ax in axes:
        ax.axhline(0, color="grey", lw=0.6)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    save(fig, "example-1-early.png")

    # The sections in time for the meshes, and for the time steps (the
    # paper's Fig. 4a-b); the right column zooms on the lift-off at 0.15.
    for names, figure in [(meshes, "example-1-sections.png"),
                          (["ex1-dt-0.025e-2", "ex1-q1-40", "ex1-dt-0.2e-2",
                            "ex1-dt-0.5e-2"], "example-1-time-step.png")]:
        fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
        for name in names:
            rows = history(output, name)
            label = ("dtau = 0.05e-2 (paper)" if name == "ex1-q1-40"
                     and "dt" in names[0] else label_of(name))
            tau = column(rows, "tau")
            for i, key in enumerate(["w(0;0)", "w(0.15;0)"]):
                axes[i][0].plot(tau, column(rows, key), label=label, lw=1)
                early = [(t, w) for t, w in zip(tau, column(rows, key))
                         if t <= 0.012]
                axes[i][1].plot(*zip(*early), label=label, lw=1,
                                marker="." if len(early) < 40 else None)
        for i, xi in enumerate(["0", "0.15"]):
            for j in range(2):
                ax = axes[i][j]
                ax.axhline(0, color="grey", lw=0.6)
                ax.set_xlabel("tau")
                ax.set_ylabel("v at xi = " + xi)
                ax.grid(alpha=0.3)
                ax.legend(fontsize=7)
            axes[i][1].set_title("xi = %s, first instants (v < 0: lifted "
                                 "off)" % xi, fontsize=10)
            axes[i][0].set_title("Example 1, section xi = " + xi, fontsize=10)
        save(fig, figure)


def plot_example_2(output):
    for name, load in [("ex2-ramp", "F/F0 = 0.1 tau"),
                       ("ex2-pulse", "F/F0 = sin^2(pi tau / 2.5)")]:
        rows = history(output, name)
        tau = column(rows, "tau")
        fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
        for key, xi in [("w(0;0)", "0"), ("w(0.15;0)", "0.15"),
                        ("w(0.5;0)", "0.5 (end)")]:
            axes[0].plot(tau, column(rows, key), label="v at xi = " + xi,
                         lw=1)
        axes[0].axhline(0, color="grey", lw=0.6)
        axes[0].set_title("Example 2, %s: sections" % load, fontsize=10)
        axes[0].set_xlabel("tau")
        axes[0].set_ylabel("v")
        axes[1].plot(tau, column(rows, "contact_fraction"), lw=1)
        axes[1].set_title("share of the beam in contact", fontsize=10)
        axes[1].set_xlabel("tau")
        axes[1].set_ylim(-0.05, 1.05)
        draw_profiles(axes[2], output, name, "v along the axis")
        for ax in axes[:2]:
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=7)
        save(fig, "example-2-%s.png" % name.split("-")[1])


def plot_example_3(output):
    meshes = ["ex3-q1-8", "ex3-q1-16", "ex3-q1-32", "ex3-q2-8", "ex3-q2-16"]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    for ax, name in zip(axes.flat[:2], ["ex3-q1-32", "ex3-q2-16"]):
        draw_profiles(ax, output, name, "Example 3, v along the xi axis, "
                      + label_of(name) + " (quarter)")
    for name in meshes:
        rows = history(output, name)
        for ax, key in zip(axes.flat[2:], ["w(0;0)", "w(0.5;0)"]):
            ax.plot(column(rows, "tau"), column(rows, key),
                    label=label_of(name), lw=1)
    for ax, xi in zip(axes.flat[2:], ["0 (centre)", "0.5 (edge mid-point)"]):
        ax.axhline(0, color="grey", lw=0.6)
        ax.set_title("v at xi = %s, eta = 0, all meshes" % xi, fontsize=10)
        ax.set_xlabel("tau")
        ax.set_ylabel("v")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    save(fig, "example-3.png")


def plot_serendipity(output):
    """The eight-node (S2) against the nine-node (Q2) element, Examples 3
    and 4: the probes in time."""
    panels = [("ex3", ["ex3-q2-16", "ex3-q2-8", "ex3-s2-16", "ex3-s2-8",
                       "ex3-s2-8-reduced"],
               [("w(0;0)", "centre"), ("w(0.5;0)", "edge mid-point")]),
              ("ex4", ["ex4-reference", "ex4-q2-15-reduced",
                       "ex4-s2-15-reduced", "ex4-s2-8-reduced",
                       "ex4-s2-15-full", "ex4-reduced"],
               [("w(0.2;0)", "node E = (0.2, 0)"), ("w(0;0)", "centre")])]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    for row, (prefix, names, probes) in zip(axes, panels):
        for name in names:
            rows = history(output, name)
            for ax, (key, _) in zip(row, probes):
                ax.plot(column(rows, "tau"), column(rows, key),
                        label=label_of(name), lw=1,
                        ls="--" if "S2" in label_of(name) else "-")
        for ax, (_, where) in zip(row, probes):
            ax.axhline(0, color="grey", lw=0.6)
            ax.set_title("Example %s: v at the %s" % (prefix[-1], where),
                         fontsize=10)
            ax.set_xlabel("tau")
            ax.set_ylabel("v")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
    save(fig, "examples-serendipity.png")


def plot_example_4(output):
    names = ["ex4-reduced", "ex4-full", "ex4-mitc", "ex4-reference"]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    for name in names:
        rows = history(output, name)
        tau = column(rows, "tau")
        axes[0][0].plot(tau, column(rows, "w(0.2;0)"), label=label_of(name),
                        lw=1)
        axes[0][1].plot(tau, column(rows, "w(0;0)"), label=label_of(name),
                        lw=1)
        axes[1][0].plot(tau, column(rows, "contact_fraction"),
                        label=label_of(name), lw=1)
    for ax, title in [(axes[0][0], "v at node E = (0.2, 0)"),
                      (axes[0][1], "v at the centre"),
                      (axes[1][0], "share of the plate in contact")]:
        ax.set_title("Example 4 (reconstructed scene): " + title, fontsize=10)
        ax.set_xlabel("tau")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    # Profiles of the reduced and the fully integrated runs side by side.
    ax = axes[1][1]
    for name, style in [("ex4-reduced", "-"), ("ex4-full", ":")]:
        for k, (tau, (x, w)) in enumerate(sorted(profiles(output,
                                                          name).items())):
            if tau in (0.1, 0.3, 0.5):
                ax.plot(x, w, style, color="C%d" % k,
                        label="%s, tau = %g" % (label_of(name), tau))
    ax.axhline(0, color="grey", lw=0.6)
    ax.set_title("v along the xi axis", fontsize=10)
    ax.set_xlabel("xi")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, "example-4.png")


def lift_off_intervals(tau, w):
    """The time intervals (first and last step) in which w < 0."""
    intervals, start = [], None
    for i, (t, x) in enumerate(zip(tau, w)):
        if x < 0 and start is None:
            start = t
        if x >= 0 and start is not None:
            intervals.append((start, tau[i - 1]))
            start = None
    if start is not None:
        intervals.append((start, tau[-1]))
    return intervals


def report(variants, output):
    """Active-set iterations per step and run times, as a Markdown table;
    for Example 1, when the paper's section xi = 0.15 is lifted off."""
    for example, name, _, _, label in variants:
        if example != 1:
            continue
        rows = history(output, name)
        # With L the half length, the paper's xi = 0.15 is x = 0.075 here
        # and its tau is 4 tau.
        key, scale = (("w(0.075;0)", 4.0) if name == "ex1-L-half"
                      else ("w(0.15;0)", 1.0))
        w = column(rows, key)
        intervals = lift_off_intervals(
            [scale * t for t in column(rows, "tau")], w)
        print("%-28s xi = 0.15 lifted off (paper's tau): %s; min v %.2e, "
              "v at the end %.3g (paper's units)"
              % (label, ", ".join("%.4g to %.4g" % i for i in intervals)
                 or "never", scale * min(w), scale * w[-1]))
    print("\n| variant | dofs | steps | active-set iterations per step, "
          "mean | max | wall time [s] |")
    print("|---|---|---|---|---|---|")
    for _, name, _, _, label in variants:
        values, _ = parse_summary(os.path.join(output, name, "summary.txt"))
        print("| %s (`%s`) | %s | %s | %.3f | %s | %.1f |"
              % (label, name, values["dofs"], values["steps"],
                 float(values["active-set iterations per step, mean"]),
                 values["active-set iterations per step, max"],
                 float(values["wall time [s]"])))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", default="1,2,3,4",
                        help="comma-separated examples to run and plot")
    parser.add_argument("--plot-only", action="store_true",
                        help="plot and report from an earlier run")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--output",
                        default=os.path.join(ROOT, "examples-output"))
    args = parser.parse_args()
    examples = [int(e) for e in args.only.split(",")]
    if any(e not in (1, 2, 3, 4) for e in examples):
        parser.error("--only takes examples among 1, 2, 3, 4, got "
                     + args.only)
    variants = [v for v in VARIANTS if v[0] in examples]
    if not args.plot_only:
        run(variants, args.build, args.output)
    os.makedirs(FIGURES, exist_ok=True)
    plots = {1: plot_example_1, 2: plot_example_2, 3: plot_example_3,
             4: plot_example_4}
    for e in examples:
        plots[e](args.output)
    if 3 in examples and 4 in examples:
        plot_serendipity(args.output)
    report(variants, args.output)


if __name__ == "__main__":
    main()
