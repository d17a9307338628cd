#!/usr/bin/env python3
"""A slab on a base layer, bonded and unbonded without separation
(Base/Interface), each against what does not go through liftoff:

- Kirchhoff's limit (H = 0.001 L, the base 1.5 H thick and a quarter as
  stiff): a large plate on a bilateral bed under a uniform pressure on a
  small square against the infinite plate in Kelvin functions
  (kelvin_square.py) with the composite D: the transformed section's about
  its neutral axis (bonded) or D_slab + D_base (unbonded). w and M_xx at
  the centre, and the largest principal stress at the four faces (slab
  top and bottom, base top and bottom) against the section's stress per
  moment E_i (z - z_axis) / D times the closed form's moment;
- a thick slab (H = 0.05 L) on a base of another Poisson ratio: the
  composite against a uniform plate of the same D and shear stiffness
  chi sum G_i H_i (a second scene that knows no base, its load and bed
  scaled by 1 / D): the same w, and moments and shear forces D times its
  own;
- a slab curled by a linear temperature difference on a bonded and an
  unbonded base, nearly free (a bed of k = 1e-3 D / L^4): the face
  stresses of the restrained curl against the layered beam's closed form
  (no axial force, no moment: curvature -E_s alpha dT H_s^2 / (12 D)
  about the composite's axis or each layer's own);
- the design outputs of an SI slab on a bonded base under a wheel: the
  largest tension of each of the four faces in summary.json and
  history.csv is the probe's at the wheel's centre (where the bottom
  faces' peak), and each is E_i (z - z_axis) / D M_1 there with the
  section in metres and pascals; the envelopes have the base's faces;
- both weights: a plate on a bilateral bed under its self-weight settles
  at q (H + rho_b / rho H_b) / (H k);
- the mass: the plate bounces on the bilateral bed as a rigid body at
  omega^2 = k H / (rho H + rho_b H_b).

    base_composite.py LIFTOFF
"""

import json
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from kelvin_square import KelvinSquare  # noqa: E402
from scenes import read_history, run_scene_or_fail, scene_text  # noqa: E402

LIFTOFF = os.path.abspath(sys.argv[1])
NU, CHI = 0.3, 5.0 / 6.0
ELL, B = 0.04, 0.03125
FACES = ("top", "bottom", "base_top", "base_bottom")


def section(interface, delta, h_b, e_b, nu_b, rho_b=1.0):
    """D, the shear stiffness, the mass and the stress per moment of each
    face of the slab (thickness delta, the plate's D = 1) on its base, in
    the plate's units: E / (1 - nu^2) = 12 / delta^3, rho = 1 / delta."""
    e_s = 12 / delta ** 3
    e_base = e_s * e_b * (1 - NU ** 2) / (1 - nu_b ** 2)
    z_s, z_b = 0.0, 0.5 * (delta + h_b)
    if interface == "bonded":
        axis_s = axis_b = e_base * h_b * z_b / (e_s * delta + e_base * h_b)
    else:
        axis_s, axis_b = z_s, z_b
    D = (e_s * (delta ** 3 / 12 + delta * (z_s - axis_s) ** 2)
         + e_base * (h_b ** 3 / 12 + h_b * (z_b - axis_b) ** 2))
    shear = CHI * (e_s * (1 - NU) / 2 * delta
                   + e_base * (1 - nu_b) / 2 * h_b)
    mass = (delta + rho_b * h_b) / delta
    per_moment = {"top": e_s * (-delta / 2 - axis_s) / D,
                  "bottom": e_s * (delta / 2 - axis_s) / D,
                  "base_top": e_base * (delta / 2 - axis_b) / D,
                  "base_bottom": e_base * (delta / 2 + h_b - axis_b) / D}
    return D, shear, mass, per_moment


def base(interface, h_b, e_b, nu_b, rho_b=1.0):
    return {"Base": {"Interface": interface, "Thickness": h_b,
                     "Modulus ratio": e_b, "Poisson ratio": nu_b,
                     "Density ratio": rho_b}}


def square_load(delta, stiffness, magnitude, cells, probes):
    return {"Analysis": {"Type": "static"},
            "Plate": {"Thickness ratio": delta, "Poisson ratio": NU},
            "Foundation": {"Model": "bilateral", "Stiffness": stiffness},
            "Discretization": {"Symmetry": "quarter", "Cells along x": cells,
                               "Cells along y": cells},
            "Loads": {"Pressure 1": {"Magnitude": magnitude,
                                     "Region": f"{-B}, {B}, {-B}, {B}"}},
            "Output": {"Write energies": "false",
                       "Probe quantities": ", ".join(probes)}}


def first_row(folder):
    return {k: v[0] for k, v in read_history(folder).items()}


def kirchhoff_limit(work, interface):
    delta, h_b, e_b = 0.001, 0.0015, 0.25
    D, _, _, per_moment = section(interface, delta, h_b, e_b, NU)
    kelvin = KelvinSquare(ELL, NU, B, D)
    probes = ["M_xx(0; 0)"] + [f"sigma_1_{f}(0; 0)" for f in FACES]
    folder = run_scene_or_fail(
        LIFTOFF, work, f"kirchhoff_{interface}",
        scene_text(square_load(delta, D / ELL ** 4, kelvin.q, 64, probes),
                   base(interface, h_b, e_b, NU)))
    row = first_row(folder)
    w, m = kelvin.at_centre(0), kelvin.at_centre(1)
    error = abs(row["w(0;0)"] / w - 1)
    check(error < 1e-3, f"{interface}, Kirchhoff: w(0, 0) {row['w(0;0)']:.6e}"
          f" against the Kelvin solution with D = {D:.6g}: {error:.2e}")
    error = abs(row["M_xx(0;0)"] / m - 1)
    check(error < 1e-2, f"{interface}, Kirchhoff: M_xx(0, 0) "
          f"{row['M_xx(0;0)']:.6e} against {m:.6e}: {error:.2e}")
    for face in FACES:
        # At the centre M_1 = M_2 = M_xx: the stress is the face's law
        # times it, and times the closed form's moment within its error.
        value = row[f"sigma_1_{face}(0;0)"]
        own = per_moment[face] * row["M_xx(0;0)"]
        error = abs(value / own - 1)
        check(error < 1e-9, f"{interface}, Kirchhoff: sigma_1_{face} "
              f"{value:.6e} = E_i (z - z_axis) / D M_xx {own:.6e}: "
              f"{error:.1e}")
        error = abs(value / (per_moment[face] * m) - 1)
        check(error < 1e-2, f"{interface}, Kirchhoff: sigma_1_{face} "
              f"against the closed form's {per_moment[face] * m:.6e}: "
              f"{error:.2e}")


def thick_slab(work, interface):
    delta, h_b, e_b, nu_b = 0.05, 0.03, 0.3, 0.2
    D, shear, _, _ = section(interface, delta, h_b, e_b, nu_b)
    stiffness, q = 400.0, 1.0 / (2 * B) ** 2
    probes = ["M_xx(0.06; 0.02)", "M_xy(0.06; 0.02)", "Q_x(0.06; 0.02)"]
    composite = first_row(run_scene_or_fail(
        LIFTOFF, work, f"thick_{interface}",
        scene_text(square_load(delta, stiffness, q, 16, probes),
                   base(interface, h_b, e_b, nu_b))))
    # The uniform plate of the same D / shear ratio: 6 chi (1 - nu) /
    # delta'^2 = shear / D.
    twin_delta = math.sqrt(6 * CHI * (1 - NU) * D / shear)
    uniform = first_row(run_scene_or_fail(
        LIFTOFF, work, f"thick_{interface}_twin",
        scene_text(square_load(twin_delta, stiffness / D, q / D, 16,
                               probes))))
    error = abs(composite["w(0;0)"] / uniform["w(0;0)"] - 1)
    check(error < 1e-9, f"{interface}, thick: w(0, 0) {composite['w(0;0)']:.8e}"
          f" = the uniform twin's (H' = {twin_delta:.5f} L): {error:.1e}")
    for name in ("M_xx(0.06;0.02)", "M_xy(0.06;0.02)", "Q_x(0.06;0.02)"):
        error = abs(composite[name] / (D * uniform[name]) - 1)
        check(error < 1e-8, f"{interface}, thick: {name} {composite[name]:.6e}"
              f" = D times the twin's: {error:.1e}")


def restrained_curl(work, interface, base_heat=0.0):
    """`base_heat`: the base's own linear difference per unit of the
    slab's (Base profile = base_heat, 0), at twice the slab's alpha."""
    delta, h_b, e_b, alpha, dt = 0.02, 0.03, 0.5, 1e-3, -1.0
    alpha_b, dt_b = 2 * alpha, base_heat * dt
    D, _, _, _ = section(interface, delta, h_b, e_b, NU)
    e_s = 12 / delta ** 3
    e_base = e_s * e_b
    # Each layer's thermal strain -alpha dT z' / H (z' from its middle: the
    # top at dT / 2 above it); the curvature that leaves no moment. Zero
    # mean strains have no axial force, so each layer's moment is its own
    # about any axis.
    kappa = -(e_s * alpha * dt * delta ** 2
              + e_base * alpha_b * dt_b * h_b ** 2) / (12 * D)
    if interface == "bonded":
        axis_s = axis_b = (e_base * h_b * 0.5 * (delta + h_b)
                           / (e_s * delta + e_base * h_b))
    else:
        axis_s, axis_b = 0.0, 0.5 * (delta + h_b)
    # Biaxial and isotropic: sigma = E (1 + nu) / (1 - nu^2) (eps - eps_T).
    exact = {
        "top": e_s * (1 + NU) * (kappa * (-delta / 2 - axis_s)
                                 - alpha * dt / 2),
        "bottom": e_s * (1 + NU) * (kappa * (delta / 2 - axis_s)
                                    + alpha * dt / 2),
        "base_top": e_base * (1 + NU) * (kappa * (delta / 2 - axis_b)
                                         - alpha_b * dt_b / 2),
        "base_bottom": e_base * (1 + NU) * (kappa * (delta / 2 + h_b - axis_b)
                                            + alpha_b * dt_b / 2)}
    heat = {"Magnitude": dt, "Expansion coefficient": alpha}
    if base_heat:
        heat.update({"Base profile": f"{base_heat}, 0",
                     "Base expansion coefficient": alpha_b})
    name = f"curl_{interface}" + ("_base" if base_heat else "")
    what = f"{interface}, restrained curl" + (" with the base's own difference"
                                        if base_heat else "")
    probes = [f"sigma_1_{f}(0; 0)" for f in FACES]
    row = first_row(run_scene_or_fail(LIFTOFF, work, name, scene_text(
        {"Analysis": {"Type": "static"},
         "Plate": {"Thickness ratio": delta, "Poisson ratio": NU},
         "Foundation": {"Model": "bilateral", "Stiffness": 1e-3},
         "Discretization": {"Cells along x": 8, "Cells along y": 8},
         "Loads": {"Temperature load 1": heat},
         "Output": {"Write energies": "false",
                    "Probe quantities": ", ".join(probes)}},
        base(interface, h_b, e_b, NU))))
    scale = max(abs(v) for v in exact.values())
    for face in FACES:
        value = row[f"sigma_1_{face}(0;0)"]
        error = abs(value - exact[face]) / scale
        check(error < 1e-3, f"{what}: sigma_1_{face} "
              f"{value:.6e} against the layered closed form "
              f"{exact[face]:.6e}: {error:.1e} of the largest")


def design_outputs(work):
    h_s, h_b, e, e_b, nu = 0.25, 0.15, 30e9, 0.3, 0.15
    plane = e / (1 - nu ** 2)
    axis = e_b * h_b * 0.5 * (h_s + h_b) / (h_s + e_b * h_b)
    D = plane * (h_s ** 3 / 12 + h_s * axis ** 2
                 + e_b * (h_b ** 3 / 12 + h_b * (0.5 * (h_s + h_b) - axis) ** 2))
    depth = {"top": -h_s / 2, "bottom": h_s / 2, "base_top": h_s / 2,
             "base_bottom": h_s / 2 + h_b}
    probes = ["M_1(0; 0)"] + [f"sigma_1_{f}(0; 0)" for f in FACES]
    folder = run_scene_or_fail(LIFTOFF, work, "design", scene_text(
        {"Units": {"System": "SI", "Length": 6, "Width": 6, "Thickness": h_s,
                   "Young's modulus": e, "Density": 2400,
                   "Subgrade modulus": 50e6, "Gravity": 0},
         "Analysis": {"Type": "static"},
         "Plate": {"Poisson ratio": nu},
         "Foundation": {"Model": "tensionless"},
         "Discretization": {"Symmetry": "quarter", "Cells along x": 12,
                            "Cells along y": 12},
         "Loads": {"Pressure 1": {"Magnitude": 0.7e6,
                                  "Region": "-0.1, 0.1, -0.1, 0.1"}},
         "Output": {"Write energies": "false", "VTU interval": 0,
                    "Write stress extremes": "true",
                    "Write stress history": "true",
                    "Write envelopes": "true",
                    "Write stress envelopes": "true",
                    "Probe quantities": ", ".join(probes)}},
        base("bonded", h_b, e_b, nu)))
    row = first_row(folder)
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    m_1 = row["M_1(0;0) [N m/m]"]
    for face in FACES:
        probe = row[f"sigma_1_{face}(0;0) [Pa]"]
        modulus = plane * (e_b if face.startswith("base") else 1)
        own = modulus * (depth[face] - axis) / D * m_1
        check(abs(probe / own - 1) < 1e-9, f"SI bonded: sigma_1_{face} at "
              f"the wheel {probe:.6e} Pa = E_i (z - z_axis) / D M_1 "
              f"{own:.6e}")
        if not face.endswith("bottom"):
            continue
        text = face.replace("_", " ")
        largest = summary[f"largest tension, {text} face"]["sigma_1 [MPa]"]
        column = row[f"max_sigma_1_{face} [Pa]"]
        # The csv's 12 digits.
        check(abs(largest * 1e6 / probe - 1) < 1e-10
              and abs(column / probe - 1) < 1e-10,
              f"SI bonded: the largest tension of the {text} face "
              f"{largest:.6f} MPa (summary), {column:.6e} Pa (history) is "
              f"the wheel's")
    with open(os.path.join(folder, "envelope.0000.vtu")) as f:
        fields = f.read()
    check(all(f"sigma_1_{face}_max" in fields for face in FACES),
          "SI bonded: the stress envelopes of all four faces")


def weights(work):
    delta, h_b, rho_b, stiffness, weight = 0.05, 0.04, 0.9, 200.0, 3.0
    _, _, mass, _ = section("bonded", delta, h_b, 0.5, 0.2, rho_b)
    folder = run_scene_or_fail(LIFTOFF, work, "weights", scene_text(
        {"Analysis": {"Type": "static"},
         "Plate": {"Thickness ratio": delta, "Poisson ratio": NU},
         "Foundation": {"Model": "bilateral", "Stiffness": stiffness},
         "Discretization": {"Cells along x": 4, "Cells along y": 4},
         "Loads": {"Self weight": weight},
         "Output": {"Write energies": "false"}},
        base("bonded", h_b, 0.5, 0.2, rho_b)))
    w = first_row(folder)["w(0;0)"]
    exact = weight * mass / stiffness
    check(abs(w / exact - 1) < 1e-10, f"self-weight of both layers: w "
          f"{w:.10e} = q (H + rho_b H_b / rho) / (H k) {exact:.10e}")


def bounce(work):
    delta, h_b, rho_b, stiffness = 0.05, 0.04, 1.4, 1e4
    _, _, mass, _ = section("unbonded", delta, h_b, 0.5, 0.2, rho_b)
    omega = math.sqrt(stiffness / mass)
    period = 2 * math.pi / omega
    folder = run_scene_or_fail(LIFTOFF, work, "bounce", scene_text(
        {"Plate": {"Thickness ratio": delta, "Poisson ratio": NU},
         "Foundation": {"Model": "bilateral", "Stiffness": stiffness},
         "Discretization": {"Cells along x": 2, "Cells along y": 2},
         "Initial conditions": {"Velocity": "1; 0; 0"},
         "Time integration": {"Time step": period / 400,
                              "End time": period / 4},
         "Output": {"Write energies": "false"}},
        base("unbonded", h_b, 0.5, 0.2, rho_b)))
    history = read_history(folder)
    # A quarter period on: the top of the rigid bounce, V / omega.
    w = history["w(0;0)"][-1]
    exact = 1 / omega
    check(abs(w / exact - 1) < 1e-4, f"rigid bounce of both masses: w at a "
          f"quarter period {w:.8e} against V / omega {exact:.8e}")


with tempfile.TemporaryDirectory() as work:
    for interface in ("bonded", "unbonded"):
        kirchhoff_limit(work, interface)
        thick_slab(work, interface)
        restrained_curl(work, interface)
        restrained_curl(work, interface, base_heat=0.6)
    design_outputs(work)
    weights(work)
    bounce(work)
finish()
