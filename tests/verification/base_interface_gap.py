#!/usr/bin/env python3
"""A slab on a base it can lift off with a gap between them
(Base/Interface gap g_i(x, y): a void where g_i > 0, a pre-compression
where g_i < 0), each case against what does not have that interface:

- a slab on a rigid base (a base 100 times as stiff as the slab on a bed
  1e8 times the interface's modulus) with g_i is the slab alone on a
  tensionless bed of modulus k_i with Foundation/Initial gap = g_i: w at
  three points, the interface's contact fraction that slab's;
- equilibrium under a load and both weights (static), with the gap: the
  bed carries the load and both weights, the interface the load and the
  slab's weight;
- in the field file the interface's own gap: interface_pressure = k_i
  (w - w_base - g_i)^+ >= 0, interface_gap = (g_i - (w - w_base))^+, and
  their product 0, g_i evaluated here from its expression; and so in an
  SI scene (g_i in m of x, y in m; the field file in m and Pa);
- both weights on a pre-compressed interface: the slab stands off the
  base by |g_i| less its weight over k_i, above the bed's surface, as a
  rigid body; the history's max_uplift the base's (0), not the slab's;
- a pulse on the gapped pair (dynamic, quarter model): the energy balance
  holds with the interface's gap work.

    base_interface_gap.py LIFTOFF
"""

import os
import sys
import tempfile

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from layers import check_equilibrium, compare  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])
DELTA, NU, K_I = 0.05, 0.3, 400.0
B = 0.0625
POINTS = "0, 0; 0.25, 0.25; 0, 0.45"
# A void under the loaded edge (y = 0.5), a pre-compression at the other
# (y = -0.5), symmetric about x = 0 for the half model. Deflections under
# the load are of order 3e-2.
GAP = "0.02 * (y + 0.5)^2 + 0.01 * x^2 - 0.008"


def gap(x, y):
    return 0.02 * (y + 0.5) ** 2 + 0.01 * x ** 2 - 0.008


def slab(stiffness, model, loads, symmetry="half", output=None):
    sections = {
        "Analysis": {"Type": "static"},
        "Plate": {"Thickness ratio": DELTA, "Poisson ratio": NU},
        "Foundation": {"Model": model, "Stiffness": stiffness},
        "Discretization": {"Symmetry": symmetry, "Cells along x": 8,
                           "Cells along y": 8},
        "Loads": loads,
        "Output": {"Write energies": "false", "Probe points": POINTS}}
    sections["Output"].update(output or {})
    return sections


def base(thickness, modulus, density=1.0, k_i=K_I, interface_gap=GAP):
    return {"Base": {"Interface": "tensionless", "Thickness": thickness,
                     "Modulus ratio": modulus, "Poisson ratio": NU,
                     "Density ratio": density, "Interface stiffness": k_i,
                     "Interface gap": interface_gap}}


def last_row(folder):
    return {k: v[-1] for k, v in read_history(folder).items()}


def run(work, name, *parts):
    return last_row(run_scene_or_fail(LIFTOFF, work, name,
                                      scene_text(*parts)))


EDGE_LOAD = {"Pressure 1": {"Magnitude": 64,
                            "Region": f"{-B}, {B}, {0.5 - 2 * B}, 0.5"}}


def rigid_base(work):
    layered = run(work, "rigid", slab(1e8 * K_I, "bilateral", EDGE_LOAD),
                  base(0.05, 100))
    alone = run(work, "on_k_i",
                slab(K_I, "tensionless", EDGE_LOAD),
                {"Foundation": {"Initial gap": GAP}})
    for point in ("0;0", "0.25;0.25", "0;0.45"):
        compare(f"rigid base: w({point}) against the slab on a tensionless "
                f"bed of k_i with that gap", layered[f"w({point})"],
                alone[f"w({point})"], 1e-3)
    compare("rigid base: the interface's contact fraction against the "
            "slab's on k_i with that gap",
            layered["interface_contact_fraction"], alone["contact_fraction"],
            5e-3)
    check(0.1 < alone["contact_fraction"] < 0.9,
          f"rigid base: the slab stands off the gap in part "
          f"({alone['contact_fraction']:.3f} in contact)")


def equilibrium_and_fields(work):
    h_b, rho_b, weight, load = 0.04, 0.9, 2.0, 8.0
    loads = {"Self weight": weight,
             "Pressure 1": {"Magnitude": load / (2 * B) ** 2,
                            "Region": f"{-B}, {B}, {-B}, {B}"}}
    folder = run_scene_or_fail(LIFTOFF, work, "weights", scene_text(
        slab(K_I, "tensionless", loads, "full",
             {"Write foundation resultant": "true", "VTU interval": 1}),
        base(h_b, 0.5, rho_b, k_i=1e4)))
    row = last_row(folder)
    slab_weight = weight * 1.0
    base_weight = weight * rho_b * h_b / DELTA
    check_equilibrium(row, load, slab_weight, base_weight)
    check(0 < row["interface_contact_fraction"] < 1,
          "equilibrium: the gap opens somewhere (interface contact fraction "
          f"{row['interface_contact_fraction']:.3f})")

    field_check(folder, gap, 1e4, "field file")


def field_check(folder, gap_of, k_i, what):
    """The field file's interface_pressure and interface_gap against
    k_i (w - w_base - g_i)^+ and (g_i - w + w_base)^+, g_i = gap_of(x, y)
    at its points."""
    mesh = meshio.read(os.path.join(folder, "solution_00000.0000.vtu"))
    f = mesh.point_data
    x, y = mesh.points[:, 0], mesh.points[:, 1]
    closing = f["w"] - f["w_base"] - gap_of(x, y)
    opening = np.maximum(-closing, 0)
    scale = float(np.max(np.abs(closing)))
    pressure = f["interface_pressure"]
    pressure_error = float(np.max(np.abs(
        pressure - k_i * np.maximum(closing, 0)))) / (k_i * scale)
    gap_error = float(np.max(np.abs(f["interface_gap"] - opening))) / scale
    product = float(np.max(pressure * opening)) / (k_i * scale * scale)
    print(f"{what}: {f['w'].dtype}, |w - w_base - g_i| up to {scale:.2e}")
    # The field files hold single precision: 6e-8 of each field, more of
    # the difference w - w_base - g_i.
    check(pressure_error < 1e-5 and gap_error < 1e-5
          and float(np.min(pressure)) >= 0 and product < 1e-6
          and float(np.max(opening)) > 1e-2 * scale,
          f"{what}: interface_pressure k_i (w - w_base - g_i)^+ within "
          f"{pressure_error:.1e}, interface_gap (g_i - w + w_base)^+ within "
          f"{gap_error:.1e}, pressure >= 0 ({float(np.min(pressure))}), "
          f"pressure x opening {product:.1e}, the gap open up to "
          f"{float(np.max(opening)):.2e}")


def si_scene(work):
    """An SI scene: g_i in m of x, y in m, the field file in m and Pa."""
    folder = run_scene_or_fail(LIFTOFF, work, "si", scene_text(
        {"Analysis": {"Type": "static"},
         "Units": {"System": "SI", "Length": 4, "Width": 4,
                   "Thickness": 0.25, "Young's modulus": 30e9,
                   "Subgrade modulus": 50e6},
         "Base": {"Interface": "tensionless", "Thickness": 0.15,
                  "Modulus ratio": 0.3, "Interface stiffness": 1e9,
                  "Interface gap": "2e-5 * (x^2 + y^2) - 1e-5"},
         "Discretization": {"Symmetry": "quarter", "Cells along x": 6,
                            "Cells along y": 6},
         "Loads": {"Pressure 1": {"Magnitude": 700e3,
                                  "Region": "-0.15, 0.15, -0.15, 0.15"}},
         "Output": {"Write energies": "false", "VTU interval": 1}}))
    field_check(folder, lambda x, y: 2e-5 * (x ** 2 + y ** 2) - 1e-5, 1e9,
                "SI field file")


def pre_compressed(work):
    """Both weights alone on a pre-compressed interface (g_i = -0.02
    everywhere): the pair sinks into the bed by the weights over k, and
    the slab stands off the base by |g_i| less its weight over k_i, above
    the bed's surface, each as a rigid body; the history's max_uplift is
    the base's (0), not the slab's rise."""
    h_b, weight, g_i = 0.04, 2.0, -0.02
    folder = run_scene_or_fail(LIFTOFF, work, "pre", scene_text(
        slab(K_I, "tensionless", {"Self weight": weight}, "quarter",
             {"VTU interval": 1}),
        base(h_b, 0.5, k_i=1e4, interface_gap=g_i)))
    row = last_row(folder)
    w = weight * (1 + h_b / DELTA) / K_I + g_i + weight / 1e4
    compare("pre-compressed: w(0, 0) against (q_s + q_b) / k + g_i + q_s / "
            "k_i", row["w(0;0)"], w, 1e-9)
    uplift = meshio.read(os.path.join(
        folder, "solution_00000.0000.vtu")).point_data["uplift"]
    check(w < 0 and row["max_uplift"] == 0 and float(np.max(uplift)) == 0,
          f"pre-compressed: max_uplift {row['max_uplift']} the base's (the "
          f"field's {float(np.max(uplift))}), not the slab's rise {-w:.2e}")


def dynamic(work):
    folder = run_scene_or_fail(LIFTOFF, work, "pulse", scene_text(
        {"Plate": {"Thickness ratio": DELTA, "Poisson ratio": NU},
         "Foundation": {"Model": "tensionless", "Stiffness": K_I},
         "Discretization": {"Symmetry": "quarter", "Cells along x": 8,
                            "Cells along y": 8},
         "Loads": {"Self weight": 2,
                   "Pressure 1": {"Magnitude": 400,
                                  "Region": f"{-B}, {B}, {-B}, {B}",
                                  "Time history":
                                  "sin(pi * tau / 0.02)^2 * (tau < 0.02)"}},
         "Time integration": {"Time step": 0.001, "End time": 0.06}},
        base(0.04, 0.5, k_i=1e4,
             interface_gap="0.002 * (x^2 + y^2) - 0.0002")))
    h = read_history(folder)
    scale = max(np.max(np.abs(h[c])) for c in ("kinetic", "strain", "work"))
    worst = np.max(np.abs(h["balance_error"])) / scale
    check(worst < 5e-3, f"pulse on a gap: the energy balance within "
          f"{worst:.1e} of the energy scale")
    check(min(h["interface_contact_fraction"]) < 0.99,
          "pulse on a gap: the slab stands off the base in part (interface "
          f"contact fraction down to {min(h['interface_contact_fraction']):.3f})")


with tempfile.TemporaryDirectory() as work:
    rigid_base(work)
    equilibrium_and_fields(work)
    si_scene(work)
    pre_compressed(work)
    dynamic(work)
finish()
