#!/usr/bin/env python3
"""A slab on a base it can lift off (Base/Interface = tensionless: the
base's own w, psi_x, psi_y and interface springs k_i that push but never
pull), each case against a scene that does not have that interface:

- a very stiff interface (k_i = 1.2e8 D / L^4, 3e8 times the bed's) under
  a thin slab pressed everywhere (a uniform pressure and a square load) is
  the unbonded base without separation (D = D_slab + D_base, w shared): w
  at the load, the slab's M_xx there against its share D_slab / D of the
  section's, the base's face stresses (of its own moments) against the
  section's law for them (7.8e-4), and the interface in contact
  everywhere (k_i 100 times softer leaves 5.5e-3 in the moment);
- a very thin and soft base (H_b = H / 100, E_b = E / 1000, nearly
  weightless) under a stiff interface is the slab alone on the bed;
- a slab lifting off a rigid base (a base 100 times as stiff as the slab on
  a bed 1e8 times the interface's modulus) is the slab alone on a
  tensionless bed of modulus k_i: w at three points, the interface's
  contact fraction that slab's contact fraction, its resultant the load;
- two slabs with a free joint on a rigid base against the two slabs on a
  tensionless bed of k_i (w on both sides of the joint and far off it),
  and in the field file the base continuous across the joint where the
  slabs jump;
- two slabs of their own sections (thickness and modulus), each loaded,
  on a rigid base against the same slabs on a tensionless bed of k_i (w
  on both slabs, the contact fraction), and the bed carrying every
  layer's weight, each slab's by its thickness, the base's its own;
- a joint on a symmetry plane (2 x 2 slabs with rotational springs, a
  base of its own, a symmetric load): the half model (x1 on its plane)
  and the quarter (x1 and y1 on planes) against the full plate, every
  history column, and the base's psi . n held on the plane where the
  slab's is not;
- equilibrium under a load and both weights (static): the bed carries the
  load and the weights of slab and base, the interface the load and the
  slab's weight;
- a dynamic pulse on the settled pair, which rebounds off the base: the
  interface lets go (its contact fraction falls below 1; in the field
  files the interface presses only where the gap is shut), the energy
  balance holds, a quarter model gives the full plate's history, a run
  stopped and resumed gives the same history.csv byte for byte, and two
  ranks give every column within 1e-9.

    base_tensionless.py LIFTOFF
"""

import filecmp
import json
import glob
import os
import sys
import tempfile

import meshio
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from layers import check_equilibrium, compare  # noqa: E402
from scenes import (merged, read_history, run_scene,  # noqa: E402
                    run_scene_or_fail, scene_text)

LIFTOFF = os.path.abspath(sys.argv[1])
DELTA, NU = 0.05, 0.3
B = 0.0625
PROBES = ["M_xx(0; 0)"]
POINTS = "0, 0; 0.25, 0.25; 0, 0.45"


def slab(stiffness, model, cells=8, loads=None, output=None, delta=DELTA,
         probes=PROBES):
    sections = {
        "Analysis": {"Type": "static"},
        "Plate": {"Thickness ratio": delta, "Poisson ratio": NU},
        "Foundation": {"Model": model, "Stiffness": stiffness},
        "Discretization": {"Symmetry": "quarter", "Cells along x": cells,
                           "Cells along y": cells},
        "Loads": loads or {},
        "Output": {"Write energies": "false",
                   "Probe quantities": ", ".join(probes)}}
    sections["Output"].update(output or {})
    return sections


def base(interface, thickness, modulus, density=1.0, k_i=0.0):
    entries = {"Interface": interface, "Thickness": thickness,
               "Modulus ratio": modulus, "Poisson ratio": NU,
               "Density ratio": density}
    if k_i:
        entries["Interface stiffness"] = k_i
    return {"Base": entries}


def run(work, name, *parts):
    history = read_history(run_scene_or_fail(LIFTOFF, work, name,
                                             scene_text(*parts)))
    return {k: v[-1] for k, v in history.items()}


PRESSED = {"Pressure 1": {"Magnitude": 100, "Region": "whole plate"},
           "Pressure 2": {"Magnitude": 64,
                          "Region": f"{-B}, {B}, {-B}, {B}"}}


def stiff_interface(work, cells=8):
    # Thin layers: each layer's own shear strain (which the unbonded
    # section shares) is negligible.
    delta, h_b, e_b = 0.005, 0.004, 0.5
    # The base's own modulus E_b / H_b and its bending stiffness in the
    # plate's units (E / (1 - nu^2) = 12 / delta^3, D = 1).
    k_b = e_b * 12 / delta ** 3 / h_b
    d_b = e_b * (h_b / delta) ** 3
    faces = ["sigma_1_base_top(0; 0)", "sigma_1_base_bottom(0; 0)"]
    scene = slab(0.4, "bilateral", cells, loads=PRESSED, delta=delta,
                 probes=PROBES + faces)
    separate = run(work, "stiff", merged(scene, {"Output": {
        "Write stress extremes": "true", "Write stress history": "true"}}),
                   base("tensionless", h_b, e_b, k_i=1e-2 * k_b))
    # The design outputs sweep the base's own faces too: under the square
    # load the base's bottom face is in its largest tension at the centre.
    with open(os.path.join(work, "stiff", "summary.json")) as f:
        largest = json.load(f)["largest tension, base bottom face"]
    probe = separate["sigma_1_base_bottom(0;0)"]
    check(abs(largest["sigma_1"] / probe - 1) < 1e-10
          and abs(separate["max_sigma_1_base_bottom"] / probe - 1) < 1e-10
          and largest["x"] == 0 and largest["y"] == 0,
          f"stiff interface: the summary's and history's largest tension of "
          f"the base's bottom face {largest['sigma_1']:.6e} is the probe's "
          f"at the load")
    shared = run(work, "unbonded", scene, base("unbonded", h_b, e_b))
    compare("stiff interface: w(0, 0) against unbonded", separate["w(0;0)"],
            shared["w(0;0)"], 1e-3)
    # The slab's own moment against its share D_slab / (D_slab + D_base)
    # of the section's.
    compare("stiff interface: the slab's M_xx(0, 0) against its share of "
            "unbonded's", separate["M_xx(0;0)"],
            shared["M_xx(0;0)"] / (1 + d_b), 1e-3)
    # The base's faces by its own bending against the unbonded section's
    # law for them.
    for face in ("base_top", "base_bottom"):
        compare(f"stiff interface: sigma_1_{face}(0, 0) of the base's own "
                "moments against unbonded's", separate[f"sigma_1_{face}(0;0)"],
                shared[f"sigma_1_{face}(0;0)"], 1e-3)
    check(separate["interface_contact_fraction"] == 1,
          "stiff interface: pressed everywhere, in contact everywhere "
          f"({separate['interface_contact_fraction']})")


def stiff_interface_heated(work):
    """The same pair curled by the slab's and the base's own temperature
    differences (the base's at twice the slab's alpha), still pressed
    everywhere: tensionless against unbonded, whose section takes both free
    moments."""
    delta, h_b, e_b = 0.005, 0.004, 0.5
    k_b = e_b * 12 / delta ** 3 / h_b
    faces = [f"sigma_1_{face}(0; 0)"
             for face in ("top", "bottom", "base_top", "base_bottom")]
    # A uniform pressure bends neither layer: what bends them is the heat.
    loads = {"Pressure 1": {"Magnitude": 100, "Region": "whole plate"},
             "Temperature load 1": {
                 "Magnitude": -1, "Expansion coefficient": 1e-4,
                 "Base profile": "0.5, 0", "Base expansion coefficient": 2e-4}}
    scene = slab(0.4, "bilateral", loads=loads, delta=delta, probes=faces)
    separate = run(work, "stiff_heated", scene,
                   base("tensionless", h_b, e_b, k_i=1e-2 * k_b))
    shared = run(work, "unbonded_heated", scene, base("unbonded", h_b, e_b))
    compare("heated, stiff interface: w(0, 0) against unbonded",
            separate["w(0;0)"], shared["w(0;0)"], 1e-3)
    for face in faces:
        name = face.replace(" ", "")
        compare(f"heated, stiff interface: {name} against unbonded's",
                separate[name], shared[name], 1e-3)
    check(separate["interface_contact_fraction"] == 1,
          "heated, stiff interface: pressed everywhere, in contact everywhere "
          f"({separate['interface_contact_fraction']})")


def held_base_heated(work):
    """A base warmed by a nonlinear profile of its own, held flat by a very
    stiff bilateral bed, under a slab pressed onto it that has no
    temperature: each of the base's faces has the fully restrained stress
    -E_b / (1 - nu_b) alpha_b (T_face - T_mean), and the slab, resting on a
    flat base, none."""
    h_b, e_b, alpha_b = 0.05, 0.5, 1e-3
    values = [1.0, 0.2, 0.0]
    mean = 0.5 * (0.5 * (values[0] + values[1]) + 0.5 * (values[1] + values[2]))
    plane = e_b * 12 * (1 + NU) / DELTA ** 3
    exact = {"base_top": -plane * alpha_b * (values[0] - mean),
             "base_bottom": -plane * alpha_b * (values[-1] - mean)}
    faces = ["top", "bottom", "base_top", "base_bottom"]
    loads = {"Pressure 1": {"Magnitude": 1, "Region": "whole plate"},
             "Temperature load 1": {
                 "Magnitude": 1, "Expansion coefficient": 1e-3,
                 "Profile": "0, 0",
                 "Base profile": ", ".join(str(v) for v in values),
                 "Base expansion coefficient": alpha_b}}
    held = run(work, "held_heated", slab(
        1e8, "bilateral", loads=loads,
        probes=[f"sigma_1_{face}(0; 0)" for face in faces]),
        base("tensionless", h_b, e_b, k_i=1e3))
    scale = max(abs(v) for v in exact.values())
    for face in ("base_top", "base_bottom"):
        value = held[f"sigma_1_{face}(0;0)"]
        error = abs(value - exact[face]) / scale
        check(error < 1e-6, f"heated base held flat: sigma_1_{face}(0, 0) "
              f"{value:.8e} against the restrained {exact[face]:.8e}: "
              f"{error:.1e} < 1e-6 of the largest")
    for face in ("top", "bottom"):
        value = held[f"sigma_1_{face}(0;0)"]
        check(abs(value) < 1e-5 * scale, f"heated base held flat: the "
              f"slab's sigma_1_{face}(0, 0) {value:.1e} is 0 to 1e-5 of the "
              "base's")


def thin_soft_base(work):
    scene = slab(400, "tensionless", loads=PRESSED)
    layered = run(work, "thin", scene,
                  base("tensionless", DELTA / 100, 1e-3, 1e-3, k_i=1e9))
    alone = run(work, "alone", scene)
    compare("thin soft base: w(0, 0) against the slab alone",
            layered["w(0;0)"], alone["w(0;0)"], 1e-3)
    compare("thin soft base: M_xx(0, 0) against the slab alone",
            layered["M_xx(0;0)"], alone["M_xx(0;0)"], 1e-3)


def on_k_i(what, layered, alone, points):
    """The slabs on a rigid base (`layered`) against the slabs on a
    tensionless bed of k_i (`alone`): w at `points`, the interface's
    contact fraction the bed's, which lets go somewhere."""
    for point in points:
        compare(f"{what}: w({point}) against the slabs on a tensionless "
                f"bed of k_i", layered[f"w({point})"], alone[f"w({point})"],
                1e-3)
    compare(f"{what}: the interface's contact fraction against the slabs' "
            "on k_i", layered["interface_contact_fraction"],
            alone["contact_fraction"], 2e-2)
    check(alone["contact_fraction"] < 0.9,
          f"{what}: the slabs lift off ({alone['contact_fraction']:.3f} in "
          "contact)")


def rigid_base(work):
    k_i = 400.0
    loads = {"Pressure 1": {"Magnitude": 64,
                            "Region": f"{-B}, {B}, {0.5 - 2 * B}, 0.5"}}
    output = {"Probe points": POINTS}
    layered = run(work, "rigid", slab(1e8 * k_i, "bilateral", loads=loads,
                                      output=output),
                  {"Discretization": {"Symmetry": "half"}},
                  base("tensionless", 0.05, 100, k_i=k_i))
    alone = run(work, "on_k_i", slab(k_i, "tensionless", loads=loads,
                                     output=output),
                {"Discretization": {"Symmetry": "half"}})
    on_k_i("rigid base", layered, alone, ("0;0", "0.25;0.25", "0;0.45"))


def jointed(work):
    """Two slabs with a free joint at x = 0, one loaded, both weighing, on a
    rigid base that runs on under the joint, against the two slabs on a
    tensionless bed of k_i."""
    k_i = 400.0
    loads = {"Self weight": 2,
             "Pressure 1": {"Magnitude": 64,
                            "Region": f"{-2 * B}, 0, {-B}, {B}"}}
    parts = [{"Discretization": {"Symmetry": "full", "Cells along x": 16,
                                 "Cells along y": 16},
              "Slabs": {"Slabs along x": 2},
              "Output": {"Probe points": "-0.05, 0; 0.05, 0; 0.4, 0.3",
                         "VTU interval": 1}}]
    layered_folder = run_scene_or_fail(
        LIFTOFF, work, "jointed_rigid",
        scene_text(slab(1e8 * k_i, "bilateral", loads=loads), *parts,
                   base("tensionless", 0.05, 100, k_i=k_i)))
    layered = {k: v[-1] for k, v in read_history(layered_folder).items()}
    alone = run(work, "jointed_on_k_i",
                slab(k_i, "tensionless", loads=loads), *parts)
    for point in ("-0.05;0", "0.05;0", "0.4;0.3"):
        compare(f"jointed, rigid base: w({point}) against the slabs on a "
                f"tensionless bed of k_i", layered[f"w({point})"],
                alone[f"w({point})"], 1e-3)
    # The base is one plate under the joint, the slabs are two.
    fields = meshio.read(os.path.join(layered_folder,
                                      "solution_00000.0000.vtu"))
    x, y = fields.points[:, 0], fields.points[:, 1]
    on_joint = np.abs(x) < 1e-9
    jump = {}
    for name in ("w", "w_base"):
        values = {}
        for yy, v in zip(y[on_joint], fields.point_data[name][on_joint]):
            values.setdefault(round(float(yy), 9), []).append(float(v))
        jump[name] = max(max(v) - min(v) for v in values.values()) / max(
            abs(fields.point_data[name]).max(), 1e-300)
    check(jump["w_base"] < 1e-6 and jump["w"] > 1e-2,
          f"jointed: across the free joint the base is continuous (jump "
          f"{jump['w_base']:.1e} of its largest w), the slabs are not "
          f"({jump['w']:.1e})")


def slab_sections(work):
    """Two slabs of their own sections (thickness and modulus) with a free
    joint at x = 0 on a rigid base, against the same slabs on a
    tensionless bed of k_i; the bed carries the load and every layer's
    weight, each slab's by its own thickness."""
    k_i, weight, h_b, rho_b = 400.0, 2.0, 0.05, 0.9
    thickness, modulus = (0.04, 0.07), (1.5, 0.7)
    # A load on each slab, beside the joint and at the far edge.
    loads = {"Self weight": weight,
             "Pressure 1": {"Magnitude": 256,
                            "Region": f"{-2 * B}, 0, {-B}, {B}"},
             "Pressure 2": {"Magnitude": 256,
                            "Region": f"{0.5 - 2 * B}, 0.5, {-B}, {B}"}}
    parts = [{"Discretization": {"Symmetry": "full", "Cells along x": 16,
                                 "Cells along y": 16},
              "Slabs": {"Slabs along x": 2,
                        "Thicknesses": ", ".join(map(str, thickness)),
                        "Modulus ratios": ", ".join(map(str, modulus))},
              "Output": {"Probe points": "-0.05, 0; 0.05, 0; -0.4, -0.3; "
                         "0.45, 0; 0.3, 0.3",
                         "Write foundation resultant": "true"}}]
    layered = run(work, "sections_rigid",
                  slab(1e8 * k_i, "bilateral", loads=loads), *parts,
                  base("tensionless", h_b, 100, rho_b, k_i=k_i))
    alone = run(work, "sections_on_k_i",
                slab(k_i, "tensionless", loads=loads), *parts)
    on_k_i("slab sections, rigid base", layered, alone,
           ("-0.05;0", "0.05;0", "-0.4;-0.3", "0.45;0", "0.3;0.3"))
    # Each slab (half the plate) weighs by its own thickness; the base by
    # its own, the same under both.
    load = 2 * 256 * (2 * B) ** 2
    slabs = weight * sum(0.5 * t / DELTA for t in thickness)
    compare("slab sections: the bed's resultant against the load and every "
            "layer's weight", layered["resultant"],
            load + slabs + weight * rho_b * h_b / DELTA, 1e-9)
    compare("slab sections: the interface's resultant against the load and "
            "the slabs' weights", layered["interface_resultant"],
            load + slabs, 1e-9)


PLANE_PROBES = {
    "Probe points": "0.02, 0.02; 0.1, 0.05; 0.3, 0.2; 0.45, 0.45",
    "Probe quantities": "M_xx(0.02; 0.1), M_yy(0.1; 0.02), "
    "sigma_1_base_bottom(0; 0.1), sigma_1_base_bottom(0.02; 0.02), "
    "sigma_1_base_top(0.3; 0.2)",
    "Write foundation resultant": "true", "VTU interval": 1}


def on_planes(symmetry):
    """2 x 2 slabs with rotational springs at the joints on a base of its
    own, under a symmetric load: on a half model the joint x1 lies on the
    plane x = 0, on a quarter both joints lie on planes."""
    cells = {"full": (16, 16), "half": (8, 16), "quarter": (8, 8)}[symmetry]
    return scene_text(
        slab(400, "tensionless", loads={
            "Self weight": 2,
            "Pressure 1": {"Magnitude": 400,
                           "Region": f"{-B}, {B}, {-B}, {B}"}},
            output=PLANE_PROBES),
        {"Discretization": {"Symmetry": symmetry, "Cells along x": cells[0],
                            "Cells along y": cells[1]},
         "Slabs": {"Slabs along x": 2, "Slabs along y": 2,
                   "Rotational stiffness": 1}},
        base("tensionless", 0.04, 0.5, k_i=1e4))


def joint_on_plane(work):
    """A joint on a symmetry plane: the slab's edge acts against its mirror
    image, the base runs on through the plane (the plane's condition on
    its own fields): the half and quarter models against the full
    plate."""
    full = run_scene_or_fail(LIFTOFF, work, "planes_full", on_planes("full"))
    history = {k: v[-1] for k, v in read_history(full).items()}
    check(history["interface_contact_fraction"] < 0.99
          and history["contact_fraction"] < 0.99,
          "joint on a plane: the slabs lift off the base "
          f"({history['interface_contact_fraction']:.3f} in contact) and "
          f"the base off the bed ({history['contact_fraction']:.3f})")
    # The base is one plate across the joints (tied: the same values).
    fields = meshio.read(os.path.join(full, "solution_00000.0000.vtu"))
    values = {}
    for p, v in zip(fields.points, fields.point_data["w_base"]):
        if abs(p[0]) < 1e-12:
            values.setdefault(round(float(p[1]), 9), []).append(float(v))
    jump = max(max(v) - min(v) for v in values.values())
    check(jump == 0, f"joint on a plane: the full plate's w_base continuous "
          f"across x1 (jump {jump})")
    for symmetry in ("half", "quarter"):
        folder = run_scene_or_fail(LIFTOFF, work, f"planes_{symmetry}",
                                   on_planes(symmetry))
        part = {k: v[-1] for k, v in read_history(folder).items()}
        # Every column but the mesh's, the iteration's and the points
        # (whose coordinates are 0 or the same).
        columns = [c for c in history if c not in (
            "tau", "cells", "dofs", "active_set_iterations",
            "active_set_cycle") and not c.startswith(("resultant_",
                                                      "max_pressure_"))]
        worst, where = max((abs(part[c] - history[c]) / max(
            abs(history[c]), 1e-300), c) for c in columns)
        check(worst < 1e-10, f"joint on a plane: the {symmetry} model's "
              f"{len(columns)} columns the full plate's within {worst:.1e} "
              f"(at most in {where})")
        # On the plane the base's rotation across it is held, the slab's is
        # not (its edge springs act against the mirror's).
        fields = meshio.read(os.path.join(folder, "solution_00000.0000.vtu"))
        on_plane = np.abs(fields.points[:, 0]) < 1e-12
        base_psi = np.abs(fields.point_data["psi_x_base"][on_plane]).max()
        slab_psi = np.abs(fields.point_data["psi_x"][on_plane]).max()
        check(base_psi == 0 and slab_psi > 1e-2 * np.abs(
            fields.point_data["psi_x"]).max(),
              f"joint on a plane, {symmetry}: psi_x_base = 0 on the plane, "
              f"psi_x up to {slab_psi:.2e}")


def equilibrium(work):
    h_b, rho_b, weight, load = 0.04, 0.9, 2.0, 8.0
    scene = slab(400, "tensionless", loads={
        "Self weight": weight,
        "Pressure 1": {"Magnitude": load / (2 * B) ** 2,
                       "Region": f"{-B}, {B}, {-B}, {B}"}},
        output={"Write foundation resultant": "true"})
    row = run(work, "weights", scene,
              {"Discretization": {"Symmetry": "full"}},
              base("tensionless", h_b, 0.5, rho_b, k_i=1e6))
    slab_weight = weight * 1.0
    base_weight = weight * rho_b * h_b / DELTA
    check_equilibrium(row, load, slab_weight, base_weight)


def pulse(symmetry, end_time=0.08):
    return scene_text(
        {"Plate": {"Thickness ratio": DELTA, "Poisson ratio": NU},
         "Foundation": {"Model": "tensionless", "Stiffness": 400},
         # The same cells: 8 along each side of the quarter.
         "Discretization": {"Symmetry": symmetry,
                            "Cells along x": 16 if symmetry == "full" else 8,
                            "Cells along y": 16 if symmetry == "full" else 8},
         "Loads": {"Self weight": 2,
                   "Pressure 1": {"Magnitude": 400,
                                  "Region": f"{-B}, {B}, {-B}, {B}",
                                  "Time history":
                                  "sin(pi * tau / 0.02)^2 * (tau < 0.02)"}},
         "Time integration": {"Time step": 0.001, "End time": end_time},
         "Output": {"VTU interval": 10 if symmetry == "full" else 0}},
        base("tensionless", 0.04, 0.5, k_i=1e4))


def every_bed_law(work):
    """The base on a bed with all its laws at once (tensionless springs on a
    symmetric initial gap, a Pasternak layer and dashpots), the base warmed
    by a profile of its own, under a pulse: the quarter model gives the full
    plate's history and the energy balance holds."""
    bed = {"Foundation": {"Shear modulus": 2, "Damping": 3,
                          "Initial gap": "0.002 * (x^2 + y^2)"},
           "Loads": {"Temperature load 1": {
               "Magnitude": -1, "Expansion coefficient": 1e-3,
               "Base profile": "1, 0.3, 0", "Base expansion coefficient": 2e-3,
               "Time history": "sin(20 * tau)"}},
           "Output": {"VTU interval": 0}}
    histories = {}
    for symmetry in ("full", "quarter"):
        folder = run_scene_or_fail(LIFTOFF, work, f"bed_laws_{symmetry}",
                                   pulse(symmetry, 0.04) + scene_text(bed))
        histories[symmetry] = read_history(folder)
        with open(os.path.join(folder, "summary.json")) as f:
            balance = json.load(f)[
                "energy balance error, largest share of the energy scale"]
        check(balance < 1e-2, f"every bed law, {symmetry}: energy balance "
              f"{balance:.1e} of the energy scale < 1e-2")
    full, quarter = histories["full"], histories["quarter"]
    worst = max(np.max(np.abs(full[c] - quarter[c]))
                / max(np.max(np.abs(full[c])), 1e-300)
                for c in full if c not in ("cells", "dofs", "balance_error"))
    check(worst < 1e-9, f"every bed law: the quarter model's history is the "
          f"full plate's within {worst:.1e} < 1e-9")


def dynamic(work):
    full = run_scene_or_fail(LIFTOFF, work, "pulse_full", pulse("full"))
    h = read_history(full)
    check(min(h["interface_contact_fraction"]) < 0.99,
          "pulse: the slab lets go of the base (interface contact fraction "
          f"down to {min(h['interface_contact_fraction']):.3f})")
    scale = max(np.max(np.abs(h[c])) for c in ("kinetic", "strain", "work"))
    worst = np.max(np.abs(h["balance_error"])) / scale
    check(worst < 1e-2, f"pulse: the energy balance within {worst:.1e} of "
          "the energy scale")
    # The field files: the interface presses only where the gap is shut,
    # and the slab stands off the base somewhere.
    largest_product, largest_gap = 0.0, 0.0
    for name in sorted(glob.glob(os.path.join(full, "solution_*.0000.vtu"))):
        fields = meshio.read(name).point_data
        largest_product = max(largest_product, float(np.max(
            fields["interface_pressure"] * fields["interface_gap"])))
        largest_gap = max(largest_gap, float(np.max(fields["interface_gap"])))
    check(largest_product == 0 and largest_gap > 0,
          f"pulse: the field files' interface_pressure x interface_gap = "
          f"{largest_product} everywhere, the gap up to {largest_gap:.2e}")
    quarter = read_history(run_scene_or_fail(LIFTOFF, work, "pulse_quarter",
                                             pulse("quarter")))
    for column in ("w(0;0)", "interface_contact_fraction",
                   "interface_resultant", "contact_fraction"):
        error = np.max(np.abs(quarter[column] - h[column])) / max(
            np.max(np.abs(h[column])), 1e-300)
        check(error < 1e-9, f"pulse: quarter model's {column} the full "
              f"plate's within {error:.1e}")
    run_scene_or_fail(LIFTOFF, work, "pulse_resumed", pulse("quarter", 0.04))
    folder, result = run_scene(LIFTOFF, work, "pulse_resumed",
                               pulse("quarter"), ["--resume"])
    check(result.returncode == 0 and filecmp.cmp(
        os.path.join(folder, "history.csv"),
        os.path.join(work, "pulse_quarter", "history.csv"), shallow=False),
        "pulse: stopped at tau = 0.04 and resumed, history.csv byte for "
        "byte the whole run's")
    two, result = run_scene(LIFTOFF, work, "pulse_two", pulse("quarter"),
                            ranks=2)
    other = read_history(two) if result.returncode == 0 else {}
    worst = max((np.max(np.abs(quarter[c] - other[c]))
                 / max(np.max(np.abs(quarter[c])), 1e-300)
                 for c in quarter if c != "balance_error"), default=1.0)
    check(result.returncode == 0 and worst < 1e-9,
          f"pulse: two ranks give every column within {worst:.1e}")


with tempfile.TemporaryDirectory() as work:
    stiff_interface(work)
    stiff_interface_heated(work)
    held_base_heated(work)
    thin_soft_base(work)
    rigid_base(work)
    jointed(work)
    slab_sections(work)
    joint_on_plane(work)
    equilibrium(work)
    dynamic(work)
    every_bed_law(work)
finish()
