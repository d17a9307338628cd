#!/usr/bin/env python3
"""The field files of a scene in SI units (issue 37) against its
dimensionless twin, converted here by hand from doc/model.md's groups
(with the force scale F0 = P, the wheel's load, not the converter's D / L):

- solution_NNNNN.0000.vtu: the coordinates are the twin's times L [m], each
  field the twin's times its unit (w F0 L^2 / D [m], psi F0 L / D [rad],
  w_dot F0 L^2 / (D t0) [m/s], the bed pressure and the stresses F0 / L^2
  [Pa], the moments F0 [N m/m], the shear forces F0 / L [N/m]; the angle of
  M_1 and the contact status unchanged), to the files' single precision;
- the `units` attribute of each field in the .pvtu names that unit;
- solution.pvd: the times are the twin's tau times t0 [s];
- envelope.0000.vtu: the extremes scaled as their fields, their times in s;
- solution_NNNNN.h5: the time attribute in s, the nodes in m, w in m.

A slab 5 m x 4 m (so that x and y have different lengths), tensionless
bed, self-weight and a 50 kN wheel dropped on it, Q2 on 6 x 6 cells.

    si_fields.py LIFTOFF
"""

import os
import re
import subprocess
import sys
import tempfile

import h5py
import meshio
import numpy as np

LIFTOFF = os.path.abspath(sys.argv[1])

E, NU, RHO, K, G = 30e9, 0.2, 2400.0, 50e6, 9.81
L, WIDTH, H, P = 5.0, 4.0, 0.25, 50e3
D = E * H**3 / (12 * (1 - NU**2))
T0 = L * L * np.sqrt(RHO * H / D)
F0 = P
DT, STEPS, INTERVAL = 2e-4, 10, 5

failures = 0


def check(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    failures += not ok


SHARED = """
subsection Discretization
  set Cells along x = 6
  set Cells along y = 6
  set Polynomial degree = 2
end
subsection Foundation
  set Model = tensionless
end
"""

SI = SHARED + f"""
subsection Units
  set System = SI
  set Length = {L}
  set Width = {WIDTH}
  set Thickness = {H}
  set Young's modulus = {E}
  set Density = {RHO}
  set Gravity = {G}
  set Subgrade modulus = {K}
end
subsection Plate
  set Poisson ratio = {NU}
end
subsection Loads
  subsection Point load 1
    set Magnitude = {P}
    set Position = 1, 0.5
  end
end
subsection Time integration
  set Time step = {DT}
  set End time = {STEPS * DT}
end
"""

TWIN = SHARED + f"""
subsection Plate
  set Aspect ratio = {WIDTH / L!r}
  set Thickness ratio = {H / L!r}
  set Poisson ratio = {NU}
end
subsection Foundation
  set Stiffness = {K * L**4 / D!r}
end
subsection Loads
  set Self weight = {RHO * G * H * L * L / F0!r}
  subsection Point load 1
    set Magnitude = {P / F0!r}
    set Position = {1 / L!r}, {0.5 / L!r}
  end
end
subsection Time integration
  set Time step = {DT / T0!r}
  set End time = {STEPS * DT / T0!r}
end
"""

OUTPUT = """
subsection Output
  set Directory = {directory}
  set VTU interval = {interval}
  set HDF5 output = true
  set Write envelopes = true
end
"""


def run(scene, directory):
    path = directory + ".prm"
    with open(path, "w") as f:
        f.write(scene + OUTPUT.format(directory=directory, interval=INTERVAL))
    subprocess.run([LIFTOFF, "--quiet", path], check=True)


W = F0 * L * L / D  # the twin's deflection unit in m
SCALES = {"w": W, "psi_x": W / L, "psi_y": W / L, "w_dot": W / T0,
          "psi_x_dot": W / (L * T0), "foundation_pressure": F0 / L**2,
          "uplift": W, "M_xx": F0, "M_yy": F0, "M_xy": F0, "Q_x": F0 / L,
          "Q_y": F0 / L, "M_1": F0, "M_2": F0, "M_1_angle": 1.0,
          "sigma_xx": F0 / L**2, "sigma_max": F0 / L**2,
          "contact_status": 1.0}
UNITS = {"w": "m", "psi_x": "rad", "w_dot": "m/s", "psi_x_dot": "rad/s",
         "foundation_pressure": "Pa", "uplift": "m", "M_xx": "N m/m",
         "Q_x": "N/m", "M_1_angle": "degree", "sigma_xx": "Pa",
         "contact_status": "1", "displacement": "m", "rotation": "rad"}


def relative(a, b):
    return np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1e-300)


def compare_fields(si, twin, scales, what):
    # The files hold single precision.
    for name, scale in scales.items():
        if name not in twin.point_data:
            check(False, f"{what}: no field {name}")
            continue
        if np.max(np.abs(twin.point_data[name])) == 0:
            continue
        error = relative(si.point_data[name], scale * twin.point_data[name])
        check(error < 1e-5, f"{what}: {name} [SI] / twin's = its unit "
              f"({error:.1e})")


def times_of(pvd):
    return [float(t) for t in re.findall(r'timestep="([^"]+)"',
                                         open(pvd).read())]


with tempfile.TemporaryDirectory() as folder:
    os.chdir(folder)
    run(SI, "si")
    run(TWIN, "twin")
    last = f"solution_{STEPS:05d}"

    si = meshio.read(f"si/{last}.0000.vtu")
    twin = meshio.read(f"twin/{last}.0000.vtu")
    error = relative(si.points, L * twin.points)
    check(error < 1e-6, f"coordinates [m] = L times the twin's ({error:.1e})")
    check(abs(si.points[:, 0].max() - L / 2) < 1e-6
          and abs(si.points[:, 1].max() - WIDTH / 2) < 1e-6,
          "the plate spans L / 2 = 2.5 m in x and 2.0 m in y")
    compare_fields(si, twin, SCALES, last)

    record = open(f"si/{last}.pvtu").read()
    for name, unit in UNITS.items():
        found = re.search(r'Name="%s"[^>]*units="([^"]*)"' % name, record)
        check(found is not None and found.group(1) == unit,
              f"units of {name} in the .pvtu: {unit!r} "
              f"({found.group(1) if found else 'none'!r})")

    si_times = np.array(times_of("si/solution.pvd"))
    twin_times = np.array(times_of("twin/solution.pvd"))
    check(len(si_times) == STEPS // INTERVAL + 1
          and relative(si_times, T0 * twin_times) < 1e-9
          and abs(si_times[-1] - STEPS * DT) < 1e-12,
          f"solution.pvd times [s] = tau t0: {list(si_times)}")

    si_envelope = meshio.read("si/envelope.0000.vtu")
    twin_envelope = meshio.read("twin/envelope.0000.vtu")
    compare_fields(si_envelope, twin_envelope,
                   {"w_max": W, "w_max_time": T0, "M_1_max": F0,
                    "foundation_pressure_max": F0 / L**2,
                    "foundation_pressure_max_time": T0},
                   "envelope")

    with h5py.File(f"si/{last}.h5", "r") as s, \
            h5py.File(f"twin/{last}.h5", "r") as t:
        check(abs(s.attrs["time"] - STEPS * DT) < 1e-12
              and s.attrs["time_units"] in ("s", b"s"),
              f"HDF5 time {s.attrs['time']} s")
        error = relative(s["nodes"][:], L * t["nodes"][:])
        check(error < 1e-6 and s["nodes"].attrs["units"] in ("m", b"m"),
              f"HDF5 nodes [m] = L times the twin's ({error:.1e})")
        error = relative(s["w"][:], W * t["w"][:])
        check(error < 1e-6 and s["w"].attrs["units"] in ("m", b"m"),
              f"HDF5 w [m] = the twin's times F0 L^2 / D ({error:.1e})")

print(f"{failures} failure(s)")
sys.exit(1 if failures else 0)
