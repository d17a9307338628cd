#!/usr/bin/env python3
"""Stresses as design quantities (Output/Write stress extremes, Write
stress history, StressExtremes), each against a reference this test
computes:

- a hard simply supported 4 m square SI slab, 0.2 m thick, under a uniform
  10 kPa, static, on a quarter model of 8 and 16 Q2 cells per side: the
  largest bottom-face tension against 6 M / H^2 with M Navier's centre
  moment (the double series summed here; 1.149 MPa), at the centre, on
  the bottom face, in MPa: rel. error 5.9e-3 and 1.4e-3, order 2; the
  largest top-face tension against 6 |M_xy| / H^2 at the corner (the
  twisting moment's series; 0.780 MPa): 1.7e-2 and 6.2e-3;
- the same slab pressed upward: the faces trade places, to the bit;
- two slabs of 0.30 and 0.20 m with a free joint on a Winkler bed, the
  plate's own thickness 0.25 m, loaded in one slab at a time: the largest
  stress of each face is 6 M / H_s^2 of the loaded slab, with M the
  history's largest M_1 (or -M_2) of the same step at the same point, and
  the summary names that slab;
- a static slab on a bilateral bed curled by a nonlinear temperature
  profile: the probes sigma_1_top and sigma_1_bottom against 6 M / H^2 of
  the probed principal moments plus each face's self-equilibrating stress
  -E alpha T_se / (1 - nu), T_se from the profile here;
- a dynamic run stopped at a checkpoint and resumed gives the summary's
  stress entries and history columns of the run without a stop, to the
  bit; two ranks give the same points, slabs and times, and the values
  within 1e-12 (the ranks' sums differ in the last bits).

    face_stresses.py LIFTOFF
"""

import json
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "common"))
from checks import check, finish  # noqa: E402
from scenes import read_history, run_scene, run_scene_or_fail, scene_text  # noqa: E402,E501

LIFTOFF = os.path.abspath(sys.argv[1])

SIDE, H, E, NU, Q = 4.0, 0.2, 30e9, 0.3, 10e3
SI = {"Units": {"System": "SI", "Length": SIDE, "Width": SIDE,
                "Thickness": H, "Young's modulus": E, "Density": 2400,
                "Gravity": 0},
      "Plate": {"Poisson ratio": NU},
      "Output": {"Write energies": "false",
                 "Write stress extremes": "true",
                 "Write stress history": "true"}}
SUPPORTED = {"Analysis": {"Type": "static"},
             "Foundation": {"Model": "none"},
             "Boundary conditions": {e: "hard simply supported"
                                     for e in ("Left", "Right", "Bottom",
                                               "Top")}}


def navier_moments(q, a, nu, n_terms=4001):
    """The simply supported square's centre moment M_xx(0, 0) and corner
    twisting moment |M_xy| by Navier's double series (Kirchhoff's moments,
    which the hard simply supported Mindlin plate has: psi = grad w_K).
    With q_mn = 16 q / (pi^2 m n) and w_mn = q_mn / (D alpha^4), alpha^2 =
    (m pi / a)^2 + (n pi / a)^2, over odd m, n:
      M_xx(centre) = sum w_mn D ((m pi/a)^2 + nu (n pi/a)^2) s_m s_n,
      |M_xy(corner)| = sum w_mn D (1 - nu) (m pi/a)(n pi/a),
    s_m = sin(m pi / 2)."""
    m = np.arange(1, n_terms + 1, 2, dtype=float)
    mm, nn = np.meshgrid(m, m, indexing="ij")
    am, an = mm * np.pi / a, nn * np.pi / a
    w = 16 * q / (np.pi ** 2 * mm * nn) / (am ** 2 + an ** 2) ** 2
    s = np.sin(mm * np.pi / 2) * np.sin(nn * np.pi / 2)
    centre = np.sum(w * (am ** 2 + nu * an ** 2) * s)
    corner = np.sum(w * (1 - nu) * am * an)
    return centre, corner


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def face(result, name):
    """The summary's largest tension of face NAME: value [MPa], x, y [m],
    slab, time [s]."""
    f = result[f"largest tension, {name} face"]
    return (f["sigma_1 [MPa]"], f["x [m]"], f["y [m]"], f["slab"],
            f["time [s]"])


def supported_slab(work):
    centre, corner = navier_moments(Q, SIDE, NU)
    # The series' truncation: the same sums on half the terms.
    coarse = navier_moments(Q, SIDE, NU, 2001)
    print(f"Navier: M_xx(centre) = {centre:.8g} N m/m "
          f"(= {centre / (Q * SIDE ** 2):.6f} q a^2, truncation "
          f"{abs(coarse[0] - centre):.1e}), |M_xy(corner)| = {corner:.8g} "
          f"(= {corner / (Q * SIDE ** 2):.6f} q a^2)")
    bottom_exact = 6 * centre / H ** 2 / 1e6
    top_exact = 6 * corner / H ** 2 / 1e6
    errors = []
    for cells in (8, 16):
        scene = scene_text(SI, SUPPORTED, {
            "Discretization": {"Symmetry": "quarter",
                               "Cells along x": cells // 2,
                               "Cells along y": cells // 2},
            "Loads": {"Pressure 1": {"Region": "whole plate",
                                     "Magnitude": Q}}})
        down = summary(run_scene_or_fail(LIFTOFF, work, f"down{cells}", scene))
        sigma, x, y, slab, _ = face(down, "bottom")
        error = abs(sigma / bottom_exact - 1)
        errors.append(error)
        print(f"{cells} cells: bottom {sigma:.8g} MPa at ({x:g}, {y:g}), "
              f"6 M / H^2 = {bottom_exact:.8g} MPa, rel. error {error:.1e}")
        limit = 8e-3 if cells == 8 else 2e-3
        check(error < limit and x == 0 and y == 0 and slab == 1,
              f"{cells} cells: largest bottom tension = 6 M_centre / H^2 "
              f"within {limit:g} ({error:.1e}), at the centre, slab 1")
        top, tx, ty, _, _ = face(down, "top")
        top_error = abs(top / top_exact - 1)
        print(f"{cells} cells: top {top:.8g} MPa at ({tx:g}, {ty:g}), "
              f"6 |M_xy| / H^2 = {top_exact:.8g} MPa, rel. error "
              f"{top_error:.1e}")
        check(top_error < 0.02 and tx == SIDE / 2 and ty == SIDE / 2,
              f"{cells} cells: largest top tension = 6 |M_xy(corner)| / H^2 "
              f"within 2 % ({top_error:.1e}), at the corner")
        check(down["largest tension"].startswith(f"{sigma:.3g} MPa, bottom "
                                                 "face, slab 1, at (0, 0) m"),
              f"{cells} cells: the line reads <{down['largest tension']}>")
        if cells == 16:
            up = summary(run_scene_or_fail(
                LIFTOFF, work, "up16", scene.replace(f"= {Q}", f"= {-Q}")))
            check(face(up, "top") == face(down, "bottom")
                  and face(up, "bottom") == face(down, "top"),
                  "pressed upward: top and bottom trade places, to the bit "
                  f"(top {face(up, 'top')[0]:.8g} MPa)")
    order = np.log2(errors[0] / errors[1])
    check(order > 1.8, f"the bottom error falls with order {order:.2f} "
          f"(> 1.8): {errors[0]:.1e} -> {errors[1]:.1e}")


def two_slabs(work):
    """Two slabs of 0.30 and 0.20 m (plate: 0.25 m), a free joint, each
    loaded alone."""
    thickness = (0.30, 0.20)
    for loaded in (0, 1):
        x_load = -1.0 if loaded == 0 else 1.0
        scene = scene_text(SI, {
            "Units": {"Thickness": 0.25, "Subgrade modulus": 80e6},
            "Analysis": {"Type": "static"},
            "Foundation": {"Model": "bilateral"},
            "Slabs": {"Slabs along x": 2,
                      "Thicknesses": ", ".join(map(str, thickness))},
            "Discretization": {"Cells along x": 8, "Cells along y": 4},
            "Loads": {"Patch load 1": {"Magnitude": 50e3, "Shape": "disc",
                                       "Size": 0.3,
                                       "Path": f"{x_load}; 0.3"}},
            "Output": {"Write moment extremes": "true"}})
        folder = run_scene_or_fail(LIFTOFF, work, f"slab{loaded}", scene)
        row = {k: v[-1] for k, v in read_history(folder).items()}
        result = summary(folder)
        h = thickness[loaded]
        for name, moment, sign in (("bottom", "max_M_1", 1),
                                   ("top", "min_M_2", -1)):
            sigma = row[f"max_sigma_1_{name} [Pa]"]
            m = sign * row[f"{moment} [N m/m]"]
            expected = 6 * m / h ** 2
            same_point = (row[f"max_sigma_1_{name}_x [m]"]
                          == row[f"{moment}_x [m]"]
                          and row[f"max_sigma_1_{name}_y [m]"]
                          == row[f"{moment}_y [m]"])
            error = abs(sigma / expected - 1)
            check(error < 1e-10 and same_point
                  and row[f"max_sigma_1_{name}_slab"] == loaded + 1,
                  f"slab {loaded + 1} (H = {h} m) loaded: {name} "
                  f"{sigma:.6g} Pa = 6 M / H_s^2 = {expected:.6g} Pa "
                  f"({error:.1e}), at its moment's point, slab "
                  f"{row[f'max_sigma_1_{name}_slab']:g}")
            got = face(result, name)
            check(got[3] == loaded + 1
                  and abs(got[0] * 1e6 / sigma - 1) < 1e-10,
                  f"slab {loaded + 1} loaded: the summary's {name} face: "
                  f"{got[0]:.6g} MPa, slab {got[3]}")


def self_equilibrating(profile):
    """T_se at the top face (s = 0) and the bed-side face (s = 1) of a
    temperature PROFILE per unit magnitude at equally spaced depths, linear
    in between: T_se = T - mean + dT_eq (s - 1/2), dT_eq = -12 int T (s -
    1/2) ds (doc/model.md, "Nonlinear profiles"; Simpson's rule is exact on
    each piece, a quadratic)."""
    t = np.asarray(profile, dtype=float)
    s = np.linspace(0, 1, len(t))
    mid_s, mid_t = (s[1:] + s[:-1]) / 2, (t[1:] + t[:-1]) / 2
    h = np.diff(s)
    mean = np.sum(h * (t[:-1] + 4 * mid_t + t[1:]) / 6)
    moment = np.sum(h * (t[:-1] * (s[:-1] - 0.5) + 4 * mid_t * (mid_s - 0.5)
                         + t[1:] * (s[1:] - 0.5)) / 6)
    linear = -12 * moment
    return (t[0] - mean + linear * (0 - 0.5), t[-1] - mean + linear * (1 - 0.5))


def curled_slab(work):
    """A static slab on a bilateral bed under a nonlinear temperature
    profile: each face's largest principal stress at a point is 6 M / H^2
    of its principal moment plus that face's self-equilibrating stress
    -E alpha T_se / (1 - nu), computed here from the profile."""
    dt, alpha, profile, point = 15.0, 1e-5, (1, 0.2, 0.1, 0), "0.7; 0.45"
    names = ("M_1", "M_2", "sigma_1_top", "sigma_1_bottom", "sigma_max")
    scene = scene_text(SI, {
        "Units": {"Subgrade modulus": 80e6},
        "Analysis": {"Type": "static"},
        "Foundation": {"Model": "bilateral"},
        "Discretization": {"Cells along x": 8, "Cells along y": 8},
        "Loads": {"Temperature load 1": {
            "Magnitude": dt, "Expansion coefficient": alpha,
            "Profile": ", ".join(map(str, profile))}},
        "Output": {"Probe quantities": ", ".join(f"{n}({point})"
                                                 for n in names)}})
    row = {k.split("(")[0]: v[-1]
           for k, v in read_history(run_scene_or_fail(
               LIFTOFF, work, "curled", scene)).items()}
    top_se, bottom_se = self_equilibrating(profile)
    top = -6 * row["M_2"] / H ** 2 - E * alpha * dt * top_se / (1 - NU)
    bottom = 6 * row["M_1"] / H ** 2 - E * alpha * dt * bottom_se / (1 - NU)
    error = max(abs(row["sigma_1_top"] / top - 1),
                abs(row["sigma_1_bottom"] / bottom - 1))
    check(error < 1e-9 and row["sigma_max"] == max(row["sigma_1_top"],
                                                   row["sigma_1_bottom"]),
          f"curled by a profile {profile}: sigma_1_top "
          f"{row['sigma_1_top']:.6g} Pa, sigma_1_bottom "
          f"{row['sigma_1_bottom']:.6g} Pa = 6 M / H^2 + the face's "
          f"-E alpha T_se / (1 - nu) (T_se {top_se:.4f}, {bottom_se:.4f}) "
          f"within {error:.1e}; sigma_max the larger")


def resumed_and_two_ranks(work):
    """A dynamic scene stopped after step 6 and resumed, and the same on
    two ranks, against the run without a stop."""
    scene = scene_text(SI, {
        "Units": {"Subgrade modulus": 50e6, "Width": 3},
        "Foundation": {"Model": "tensionless"},
        "Slabs": {"Slabs along x": 2, "Thicknesses": "0.22, 0.18"},
        "Discretization": {"Cells along x": 8, "Cells along y": 6},
        "Linear solver": {"Direct solver package": "klu"},
        "Time integration": {"Time step": 5e-4, "End time": 0.006},
        "Loads": {"Point load 1": {"Magnitude": 60e3,
                                   "Position": "0.9, 0.4",
                                   "Time history": "sin(400*t)"}}})

    def stress_entries(folder):
        s = summary(folder)
        history = read_history(folder)
        columns = {k: v for k, v in history.items() if "sigma" in k}
        return ({k: v for k, v in s.items()
                 if k.startswith("largest tension")},
                columns)

    whole = stress_entries(run_scene_or_fail(LIFTOFF, work, "whole", scene))
    stop = scene + "subsection Time integration\n  set End time = 0.003\nend\n" \
        "subsection Checkpoint\n  set Interval = 6\nend\n"
    folder, first = run_scene(LIFTOFF, work, "resumed", stop)
    folder, second = run_scene(LIFTOFF, work, "resumed", scene, ["--resume"])
    resumed = stress_entries(folder)
    same_columns = all(np.array_equal(whole[1][k], resumed[1][k])
                       for k in whole[1]) and whole[1].keys() == resumed[1].keys()
    check(first.returncode == 0 and second.returncode == 0
          and whole[0] == resumed[0] and same_columns,
          "resumed after step 6: the summary's stress entries and "
          f"{len(whole[1])} history columns as without a stop, to the bit "
          f"({whole[0]['largest tension']})")
    folder, two = run_scene(LIFTOFF, work, "two_ranks", scene, ranks=2)
    if two.returncode != 0:
        print(two.stderr)
    on_two = stress_entries(folder)
    # The two ranks' sums differ in the last bits (assembly, the bed's
    # sums): the same point, slab and time, the values within 1e-12.
    worst = max(abs(a[f"largest tension, {n} face"]["sigma_1 [MPa]"]
                    / b[f"largest tension, {n} face"]["sigma_1 [MPa]"] - 1)
                for a, b in [(whole[0], on_two[0])] for n in ("top", "bottom"))
    places = all({k: v for k, v in whole[0][f"largest tension, {n} face"].items()
                  if k != "sigma_1 [MPa]"}
                 == {k: v for k, v in on_two[0][f"largest tension, {n} face"].items()
                     if k != "sigma_1 [MPa]"} for n in ("top", "bottom"))
    columns = max(np.max(np.abs(whole[1][k] - on_two[1][k])
                         / np.maximum(np.abs(whole[1][k]), 1e-300))
                  for k in whole[1])
    check(two.returncode == 0 and places and worst < 1e-12 and columns < 1e-12,
          "two ranks: the largest tension of each face at the same point, "
          f"slab and time as on one rank, the values within {worst:.1e} "
          f"(< 1e-12), the history columns within {columns:.1e}")


with tempfile.TemporaryDirectory() as work:
    supported_slab(work)
    two_slabs(work)
    curled_slab(work)
    resumed_and_two_ranks(work)
finish()
