#!/usr/bin/env python3
"""Westergaard's interior, edge and corner loads beside liftoff
(doc/westergaard.md): static runs of large SI slabs on a bilateral bed (the
dense liquid of the closed forms), on two meshes each (the mesh error), a
thin twin of the same stiffness D (the thick plate's share), and the same
slab on liftoff's tensionless bed, with and without its weight. Prints the
tables of doc/westergaard.md and draws doc/figures/westergaard-edge.png
(the bending stress along the line from the edge under the load inwards).

    /usr/bin/python3 scripts/westergaard.py --executable build/liftoff \\
        --output westergaard/ [--figure doc/figures/westergaard-edge.png]

The closed forms are those of Ioannides, Thompson & Barenberg (1985),
"Westergaard solutions reconsidered", Transportation Research Record 1043,
pp. 13-23: Westergaard's interior and edge formulas as corrected there and
their corner formulas fitted to finite-element results.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liftoff_runs import override_text, read_csv, run_scene  # noqa: E402

# The slab and the wheel: the tutorial's pavement (doc/tutorial.md) and a
# 50 kN wheel on a disc of radius 0.15 m (707 kPa).
E, NU, H, K, RHO = 30e9, 0.15, 0.25, 50e6, 2400.0
P, A = 50e3, 0.15
EULER_GAMMA = 0.5772156649015329


def radius_of_relative_stiffness(e=E, h=H):
    return (e * h**3 / (12 * (1 - NU**2) * K)) ** 0.25


ELL = radius_of_relative_stiffness()
C_SQUARE = 1.772 * A  # the side of the square of the disc's area


def westergaard():
    """Stress [Pa] at the face in tension and deflection [m] of the three
    cases, as Ioannides, Thompson & Barenberg (1985) give them."""
    l, a = ELL, A
    interior_stress = (3 * (1 + NU) * P / (2 * math.pi * H**2)
                       * (math.log(2 * l / a) + 0.5 - EULER_GAMMA)
                       + 3 * (1 + NU) * P / (64 * H**2) * (a / l) ** 2)
    interior_w = P / (8 * K * l**2) * (
        1 + (math.log(a / (2 * l)) + EULER_GAMMA - 1.25)
        / (2 * math.pi) * (a / l) ** 2)
    edge_stress = (3 * (1 + NU) * P / (math.pi * (3 + NU) * H**2)
                   * (math.log(E * H**3 / (100 * K * a**4)) + 1.84
                      - 4 * NU / 3 + (1 - NU) / 2
                      + 1.18 * (1 + 2 * NU) * a / l))
    edge_w = (math.sqrt(2 + 1.2 * NU) * P / math.sqrt(E * H**3 * K)
              * (1 - (0.76 + 0.4 * NU) * a / l))
    corner_stress = 3 * P / H**2 * (1 - (C_SQUARE / l) ** 0.72)
    corner_w = P / (K * l**2) * (1.205 - 0.69 * C_SQUARE / l)
    return {"interior": (interior_stress, interior_w),
            "edge": (edge_stress, edge_w),
            "corner": (corner_stress, corner_w)}


def exact_interior():
    """The infinite Kirchhoff plate under the disc, by the Hankel transform
    (as tests/verification/westergaard_stress.py): the stress at the centre
    [Pa] and the deflection there [m], to check the interior forms."""
    import numpy as np
    from scipy import integrate, special
    d = E * H**3 / (12 * (1 - NU**2))
    q = P / (math.pi * A * A)
    zeros = np.concatenate([[0.0], special.jn_zeros(1, 4000) / A])

    def integral(f):
        return sum(integrate.quad(f, lo, hi)[0]
                   for lo, hi in zip(zeros[:-1], zeros[1:]))
    w = q * A * integral(lambda s: special.j1(s * A) / (d * s**4 + K))
    m = (1 + NU) / 2 * q * A * integral(
        lambda s: s**2 * special.j1(s * A) * d / (d * s**4 + K))
    return 6 * m / H**2, w


# Each case: the slab (m), the model, the load and the points read. The
# slabs reach 6 m (6.3 l) from the load on every side but the loaded edges:
# an 8 m slab (4.2 l) added 1.3 % to the thin twin's interior deflection
# (0.1400 mm against 0.1383 mm on a 16 m slab, 0.1381 mm infinite).
CASES = {
    "interior": dict(length=12, width=12, symmetry="quarter",
                     cells=lambda n: (3 * n // 2, 3 * n // 2), load="disc",
                     centre=(0, 0), stress_point=(0, 0), w_point=(0, 0)),
    "edge": dict(length=12, width=6, symmetry="half",
                 cells=lambda n: (3 * n // 2, 3 * n // 2), load="disc",
                 centre=(0, 3 - A), stress_point=(0, 3), w_point=(0, 3)),
    "corner": dict(length=6, width=6, symmetry="full",
                   cells=lambda n: (3 * n // 2, 3 * n // 2), load="square",
                   centre=(3 - C_SQUARE / 2, 3 - C_SQUARE / 2),
                   stress_point=None, w_point=(3, 3)),
}
# Cells per 4 m of slab: 0.125, 0.0625 and 0.03125 m (Q2), the load's
# radius 1.2, 2.4 and 4.8 cells.
MESHES = (32, 64, 128)
FINE = MESHES[-1]
# Points inwards from the edge under the load, for the edge's profile.
EDGE_OFFSETS = [0, 0.0125, 0.025, 0.0375, 0.05, 0.0625, 0.075, 0.1, 0.125,
                0.15, 0.2, 0.3, 0.5]


def scene(case, n, bed="bilateral", gravity=0.0, thin=False):
    """The SI scene of a case on n cells per 4 m of slab. The thin twin has
    H / 5 and E 125 times larger: the same D, so the same l and the same
    closed forms, with a plate 25 times stiffer in shear relative to its
    bending."""
    c = CASES[case]
    h, e = (H / 5, E * 125) if thin else (H, E)
    nx, ny = c["cells"](n)
    x, y = c["centre"]
    probes = ["w(%g; %g)" % c["w_point"]]
    quantities = []
    if case == "interior":
        quantities = ["sigma_xx(0; 0)", "M_xx(0; 0)"]
    elif case == "edge":
        quantities = ["M_xx(0; %g)" % (3 - d) for d in EDGE_OFFSETS]
    if c["load"] == "disc":
        shape, size, pressure = "disc", "%.6g" % (2 * A), P / (math.pi * A * A)
    else:
        shape, size = "rectangle", "%.6g, %.6g" % (C_SQUARE, C_SQUARE)
        pressure = P / C_SQUARE**2
    text = """
subsection Units
  set System           = SI
  set Length           = %g
  set Width            = %g
  set Thickness        = %.17g
  set Young's modulus  = %.17g
  set Density          = %g
  set Gravity          = %g
  set Subgrade modulus = %g
end
subsection Plate
  set Poisson ratio = %g
end
subsection Foundation
  set Model = %s
end
subsection Analysis
  set Type = static
end
subsection Discretization
  set Symmetry          = %s
  set Cells along x     = %d
  set Cells along y     = %d
  set Polynomial degree = 2
end
subsection Loads
  subsection Patch load 1
    set Magnitude = %.17g
    set Shape     = %s
    set Size      = %s
    set Path      = %.17g; %.17g
  end
end
subsection Time integration
  set Time step = 1
  set End time  = 1
end
subsection Output
  set VTU interval          = 0
  set Write energies        = false
  set Write moment extremes = true
  set Probe points          = %s
  set Probe quantities      = %s
end
""" % (c["length"], c["width"], h, e, RHO, gravity, K, NU, bed,
        c["symmetry"], nx, ny, pressure, shape, size, x, y,
        "; ".join(p[2:-1].replace(";", ",") for p in probes),
        ", ".join(quantities))
    return text


def run(executable, output, case, n, **kwargs):
    label = "%s-n%d-%s%s%s" % (case, n, kwargs.get("bed", "bilateral"),
                               "-weight" if kwargs.get("gravity") else "",
                               "-thin" if kwargs.get("thin") else "")
    directory = os.path.join(output, label)
    text = scene(case, n, **kwargs) + override_text(
        ["Output/Directory=" + directory])
    run_scene(executable, text, directory)
    return read_csv(os.path.join(directory, "history.csv"))[-1]


def stress_of(case, row, h):
    """The stress [Pa] liftoff gives for the case, as 6 M / H^2 with the
    thick slab's H (the thin twin's moments are read as the thick slab's
    stress: the closed forms depend on D alone, but for the factor 6 / H^2)."""
    if case == "interior":
        return 6 * row["M_xx(0;0) [N m/m]"] / h**2
    if case == "edge":
        return 6 * row["M_xx(0;3) [N m/m]"] / h**2
    # The corner's largest tension is on the top face: the most negative M_2.
    return -6 * row["min_M_2 [N m/m]"] / h**2


def w_of(case, row, gravity):
    x, y = CASES[case]["w_point"]
    w = row["w(%g;%g) [m]" % (x, y)]
    # The weight's settlement rho g H / k, uniform where the slab stays on
    # its bed.
    return w - (RHO * gravity * H / K if gravity else 0.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--executable", required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--figure")
    parser.add_argument("--closed-forms-only", action="store_true",
                        help="print the closed forms and make no run")
    args = parser.parse_args()
    closed = westergaard()
    print("l = %.4f m, a / l = %.4f, c = %.4f m" % (ELL, A / ELL, C_SQUARE))
    stress, w = exact_interior()
    print("interior, exact infinite Kirchhoff plate: %.5g MPa, %.5g mm; "
          "ITB 1985: %.5g MPa (%+.3f %%), %.5g mm (%+.3f %%)" % (
              stress * 1e-6, w * 1e3, closed["interior"][0] * 1e-6,
              100 * (closed["interior"][0] / stress - 1),
              closed["interior"][1] * 1e3,
              100 * (closed["interior"][1] / w - 1)))
    if args.closed_forms_only:
        for case, (s_, w_) in closed.items():
            print("%s: %.5g MPa, %.5g mm" % (case, s_ * 1e-6, w_ * 1e3))
        return
    rows = {}
    for case in ("interior", "edge", "corner"):
        for n in MESHES:
            rows[case, n] = run(args.executable, args.output, case, n)
        rows[case, "thin"] = run(args.executable, args.output, case, FINE,
                                 thin=True)
        rows[case, "tensionless"] = run(args.executable, args.output, case,
                                        FINE, bed="tensionless", gravity=9.81)
        rows[case, "weightless"] = run(args.executable, args.output, case,
                                       FINE, bed="tensionless")
    coarse, middle = MESHES[-3], MESHES[-2]
    keys = MESHES + ("thin", "tensionless", "weightless")
    print("\n| case | Westergaard (ITB 1985) | liftoff, %d / %d / %d cells "
          "per 4 m | last halving | liftoff / Westergaard - 1 | thin twin "
          "| thin / Westergaard - 1 | tensionless, weight | tensionless, "
          "weightless |" % MESHES)
    print("|---|---|---|---|---|---|---|---|---|")
    for case in ("interior", "edge", "corner"):
        ws, ww = closed[case]
        s = {key: stress_of(case, rows[case, key], H) for key in keys}
        w = {key: w_of(case, rows[case, key],
                       9.81 if key == "tensionless" else 0)
             for key in keys}
        for name, closed_value, got, scale, unit in (
                ("stress", ws, s, 1e-6, "MPa"),
                ("deflection", ww, w, 1e3, "mm")):
            print("| %s %s [%s] | %.4g | %.4g / %.4g / %.4g | %+.2f %% | "
                  "%+.2f %% | %.4g | %+.2f %% | %.4g | %.4g |" % (
                      case, name, unit, closed_value * scale,
                      got[coarse] * scale, got[middle] * scale,
                      got[FINE] * scale,
                      100 * (got[FINE] / got[middle] - 1),
                      100 * (got[FINE] / closed_value - 1),
                      got["thin"] * scale,
                      100 * (got["thin"] / closed_value - 1),
                      got["tensionless"] * scale,
                      got["weightless"] * scale))
    for key in (FINE, "thin", "tensionless", "weightless"):
        row = rows["corner", key]
        print("corner, %s: largest top tension at (%.4g, %.4g) m, %.3f m from "
              "the corner along the diagonal; contact fraction %.4f"
              % (key, row["min_M_2_x [m]"], row["min_M_2_y [m]"],
                 math.hypot(3 - row["min_M_2_x [m]"],
                            3 - row["min_M_2_y [m]"]),
                 row["contact_fraction"]))
    for key in MESHES + ("thin",):
        row = rows["edge", key]
        profile = [6 * row["M_xx(0;%g) [N m/m]" % (3 - d)] / H**2
                   for d in EDGE_OFFSETS]
        best = max(range(len(profile)), key=lambda i: profile[i])
        print("edge, %s: sigma_xx [MPa] inwards from the edge at %s m: %s; "
              "largest %.4g MPa at %g m; largest M_1 over the slab %.4g MPa "
              "at (%.4g, %.4g) m" % (
                  key, ", ".join("%g" % d for d in EDGE_OFFSETS),
                  ", ".join("%.4g" % (p * 1e-6) for p in profile),
                  profile[best] * 1e-6, EDGE_OFFSETS[best],
                  6 * row["max_M_1 [N m/m]"] / H**2 * 1e-6,
                  row["max_M_1_x [m]"], row["max_M_1_y [m]"]))
    if args.figure:
        draw_edge(rows, closed["edge"][0], args.figure)


def draw_edge(rows, closed_stress, figure):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for key, label, style in ((FINE, "liftoff, H = 0.25 m (Mindlin)", "o-"),
                              (MESHES[-2], "the same, cells twice as long",
                               "x--"),
                              ("thin", "thin twin, same D (H / 5), "
                               "6 M / 0.25^2", "s-")):
        row = rows["edge", key]
        ax.plot([d * 100 for d in EDGE_OFFSETS],
                [6 * row["M_xx(0;%g) [N m/m]" % (3 - d)] / H**2 * 1e-6
                 for d in EDGE_OFFSETS], style, label=label, ms=4)
    ax.axhline(closed_stress * 1e-6, color="k", lw=0.8,
               label="Westergaard at the edge (ITB 1985)")
    ax.set_ylim(0.9, 2.25)
    ax.set_xlabel("distance from the edge under the wheel [cm]")
    ax.set_ylabel("sigma_xx = 6 M_xx / H^2, bottom face [MPa]")
    ax.set_title("Edge load: 50 kN on a disc of 0.15 m radius at the edge")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figure, dpi=110)
    print("wrote " + figure)


if __name__ == "__main__":
    main()
