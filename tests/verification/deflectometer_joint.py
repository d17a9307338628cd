#!/usr/bin/env python3
"""scripts/liftoff-backcalc --joint, round trip: the load transfer
efficiency of a deflectometer test at a joint made by liftoff with a known
joint stiffness AGG = 2e8 N/m^2 (f = AGG / (k l) = 4.2) is fitted back.
The test: 40 kN static on the 150 mm plate tangent to the joint y = 0 of
two 3 m x 3 m slabs 0.25 m thick (E = 30 GPa, nu = 0.15) on a bilateral
bed of k = 50 MPa/m, half model, 6 x 12 cells Q2; LTE = 100 d(0.305) /
d(0), the sensors 150 and 155 mm either side of the joint.

- scripts/lte_fits.py: Crovetti's and Ioannides and Hammons' fits and
  their inverses, f -> LTE -> f within 1e-12 at f = 0.01 to 1000;
- the start, Ioannides and Hammons' fit inverted (for a load at the joint
  and w at its faces, not these sensors), is within a factor 3 of AGG;
- the fit (step tolerance 1e-10 in ln AGG) gives AGG within 1e-6 and the
  LTE within 1e-6 points;
- refused in one line (exit 1): a sensor of --lte-sensors missing from
  the basin, a scene without a joint, a basin whose LTE is above 100 %.

One joint of several: three slabs along y (3 m x 9 m, half model, 6 x 18
cells), `Shear stiffness = 2e8, 0` (y1 stiff, y2 free), the test at y1.
`--joint-name y1` fits y1's AGG back within 1e-6 and every run keeps y2 at
0 (its used_parameters.prm); without --joint-name, or with a joint the
scene has not, refused naming the joints (the tool wrote one value for
every joint before: AGG 2.1188e8, y2 made stiff, exit 0).

A mesh file's joint: tests/meshes/two_slabs.msh (1 m x 1 m, the curve
Joint at x = 0, `Mesh tags = Joint: joint`) in a folder of its own with a
template beside it that names it relatively (run from elsewhere); the
load tangent to the joint, AGG = 2e8 fitted back within 1e-6 (refused
before: "needs a scene with a joint (Slabs along x or y >= 2)").

    deflectometer_joint.py LIFTOFF
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
from checks import check, finish  # noqa: E402
import lte_fits  # noqa: E402

BACKCALC = os.path.join(HERE, "..", "..", "scripts", "liftoff-backcalc")
LIFTOFF = os.path.abspath(sys.argv[1])
AGG = 2e8

SCENE = f"""
subsection Analysis
  set Type = static
end
subsection Units
  set System = SI
  set Length = 3
  set Width = 6
  set Thickness = 0.25
  set Young's modulus = 30e9
  set Density = 2400
  set Gravity = 0
  set Subgrade modulus = 50e6
end
subsection Plate
  set Poisson ratio = 0.15
end
subsection Foundation
  set Model = bilateral
end
subsection Discretization
  set Symmetry = half
  set Cells along x = 6
  set Cells along y = 12
  set Polynomial degree = 2
end
subsection Slabs
  set Slabs along y = 2
  set Shear stiffness = {AGG}
end
subsection Loads
  subsection Deflectometer 1
    set Peak force = 40e3
    set Pulse shape = constant
    set Position = 0, -0.15
    set Sensor offsets = 0, 0.305, 0.61
    set Sensor direction = 0, 1
  end
end
subsection Output
  set Directory = truth
  set Write energies = false
end
"""


THREE_SLABS = SCENE.replace("Width = 6", "Width = 9").replace(
    "Cells along y = 12", "Cells along y = 18").replace(
    "Slabs along y = 2", "Slabs along y = 3").replace(
    f"Shear stiffness = {AGG}", f"Shear stiffness = {AGG}, 0").replace(
    "Position = 0, -0.15", "Position = 0, -1.65").replace(
    "Directory = truth", "Directory = three")

MESH_SCENE = f"""
subsection Analysis
  set Type = static
end
subsection Units
  set System = SI
  set Length = 1
  set Thickness = 0.25
  set Young's modulus = 30e9
  set Density = 2400
  set Gravity = 0
  set Subgrade modulus = 50e6
end
subsection Plate
  set Poisson ratio = 0.15
end
subsection Foundation
  set Model = bilateral
end
subsection Discretization
  set Shape = mesh file
  set Mesh file = two_slabs.msh
  set Polynomial degree = 2
end
subsection Boundary conditions
  set Mesh tags = Joint: joint
end
subsection Slabs
  set Shear stiffness = {AGG}
end
subsection Loads
  subsection Deflectometer 1
    set Peak force = 40e3
    set Pulse shape = constant
    set Position = -0.15, 0
    set Sensor offsets = 0, 0.305, 0.4
    set Sensor direction = 1, 0
  end
end
subsection Output
  set Directory = mesh_truth
  set Write energies = false
end
"""


def fits():
    worst = 0.0
    for f in [0.01, 0.1, 1, 10, 100, 1000]:
        for a_over_l in [0.1, 0.2]:
            worst = max(worst, abs(lte_fits.ioannides_hammons_inverse(
                lte_fits.ioannides_hammons(f, a_over_l), a_over_l) / f - 1))
        worst = max(worst, abs(lte_fits.crovetti_inverse(
            lte_fits.crovetti(f)) / f - 1))
    check(worst < 1e-12, f"the fits' inverses: f -> LTE -> f within "
          f"{worst:.1e}")


def backcalc(basin, output, *options, scene="scene.prm"):
    return subprocess.run(
        [sys.executable, BACKCALC, "--joint", basin, "--scene", scene,
         "--thickness", "0.25", "--poisson", "0.15", "--executable",
         LIFTOFF, "--output", output, *options], capture_output=True,
        text=True)


def round_trip():
    done = backcalc("truth/basin.csv", "fit", "--tolerance", "1e-10")
    print(done.stdout + done.stderr)
    start = re.search(r"\(Ioannides-Hammons\): AGG = \S+, (\S+) N/m\^2",
                      done.stdout)
    fitted = re.search(r"fitted: +AGG = (\S+) N/m\^2", done.stdout)
    residual = re.search(r"residual (\S+) points", done.stdout)
    if done.returncode != 0 or not (start and fitted and residual):
        check(False, "the joint's fit runs")
        return
    agg0, agg = float(start.group(1)), float(fitted.group(1))
    check(1 / 3 < agg0 / AGG < 3, f"the start, AGG = {agg0:.4g}, within a "
          f"factor 3 of {AGG:g}")
    check(abs(agg / AGG - 1) < 1e-6 and abs(float(residual.group(1))) < 1e-6,
          f"AGG back to {agg / AGG - 1:.1e}, the LTE to "
          f"{float(residual.group(1)):.1e} points")


def refusals():
    with open("no_joint.prm", "w") as f:
        f.write(SCENE.replace("Slabs along y = 2", "Slabs along y = 1"))
    with open("above.csv", "w") as f:
        f.write("offset [m],peak_w [m]\n0,1e-4\n0.305,1.2e-4\n0.61,9e-5\n")
    for what, basin, options, scene, cause in [
            ("a missing sensor", "truth/basin.csv",
             ["--lte-sensors", "0,0.2"], "scene.prm", "no sensor at 200 mm"),
            ("a scene without a joint", "truth/basin.csv", [],
             "no_joint.prm", "needs a scene with a joint"),
            ("an LTE above 100 %", "above.csv", [], "scene.prm",
             "the measured LTE, 120 %")]:
        done = backcalc(basin, "refused", *options, scene=scene)
        lines = done.stderr.strip().splitlines()
        check(done.returncode == 1 and len(lines) == 1 and cause in lines[0]
              and not os.path.exists("refused"),
              f"{what}: refused in one line ({lines[-1] if lines else ''})")


def fitted(done, what):
    """AGG as the fit printed it, or None (a failed check)."""
    print(done.stdout + done.stderr)
    found = re.search(r"fitted: +AGG = (\S+) N/m\^2", done.stdout)
    if done.returncode != 0 or not found:
        check(False, f"{what}: the fit runs")
        return None
    return float(found.group(1))


def one_of_several():
    """Three slabs, y1 stiff and y2 free; the test at y1."""
    with open("three.prm", "w") as f:
        f.write(THREE_SLABS)
    subprocess.run([LIFTOFF, "--quiet", "three.prm"], check=True,
                   stdout=subprocess.DEVNULL)
    for what, options, cause in [
            ("no --joint-name", [], "has the joints y1, y2: name the one"),
            ("--joint-name y3", ["--joint-name", "y3"],
             "--joint-name y3: the scene three.prm has the joints y1, y2")]:
        done = backcalc("three/basin.csv", "refused", *options,
                        scene="three.prm")
        lines = done.stderr.strip().splitlines()
        check(done.returncode == 1 and len(lines) == 1 and cause in lines[0]
              and not os.path.exists("refused"),
              f"three slabs, {what}: refused in one line "
              f"({lines[-1] if lines else ''})")
    agg = fitted(backcalc("three/basin.csv", "three_fit", "--tolerance",
                          "1e-10", "--joint-name", "y1", scene="three.prm"),
                 "three slabs, --joint-name y1")
    if agg is None:
        return
    kept = []
    for run in sorted(os.listdir("three_fit/runs")):
        with open(os.path.join("three_fit/runs", run,
                               "used_parameters.prm")) as f:
            entry = re.search(r"set Shear stiffness += (.*)", f.read())
        kept.append([float(v) for v in entry.group(1).split(",")][1:])
    check(abs(agg / AGG - 1) < 1e-6 and kept
          and all(values == [0.0] for values in kept),
          f"three slabs, --joint-name y1: AGG back to {agg / AGG - 1:.1e}, "
          f"y2 kept at 0 in all {len(kept)} runs")


def mesh_joint():
    """A mesh file's joint, the template beside its mesh, run from
    elsewhere."""
    os.mkdir("mesh")
    shutil.copy(os.path.join(HERE, "..", "meshes", "two_slabs.msh"), "mesh")
    with open("mesh/joint.prm", "w") as f:
        f.write(MESH_SCENE)
    subprocess.run([LIFTOFF, "--quiet", "mesh/joint.prm"], check=True,
                   stdout=subprocess.DEVNULL)
    agg = fitted(backcalc("mesh_truth/basin.csv", "mesh_fit", "--tolerance",
                          "1e-10", scene="mesh/joint.prm"),
                 "a mesh file's joint")
    if agg is not None:
        check(abs(agg / AGG - 1) < 1e-6,
              f"a mesh file's joint: AGG back to {agg / AGG - 1:.1e}")


fits()
with tempfile.TemporaryDirectory() as folder:
    os.chdir(folder)
    with open("scene.prm", "w") as f:
        f.write(SCENE)
    subprocess.run([LIFTOFF, "--quiet", "scene.prm"], check=True,
                   stdout=subprocess.DEVNULL)
    refusals()
    round_trip()
    one_of_several()
    mesh_joint()
finish()
