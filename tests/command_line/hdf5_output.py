#!/usr/bin/python3
"""HDF5 + XDMF output read back with h5py, against the run's other outputs.

    hdf5_output.py OUTPUT_DIRECTORY

solution.xdmf names one solution_NNNNN.h5 per output, at the times of
solution.pvd; in each, w at the node (0, 0) equals history.csv's probe
w(0;0) at that time (to single precision: the fields are stored as float),
the displacement vector is (0, 0, w) and the rotation (psi_x, psi_y, 0) at
every node, and the mesh is the plate's meshed part in the plane z = 0.
Every HDF data item of solution.xdmf has the shape of the data set it
names (after a resume of an adaptive run too: the mesh, and so the sizes,
differ between outputs).
Each .h5 says itself what it holds: its time tau and step as attributes
of the file, and the unit of each data set (doc/model.md's scales: w in
F0 L^2 / D, ...) as the data set's attribute `units`, and the moments'
sign convention as the file's attribute `moment_sign_convention`.
Exit 77 without h5py (Debian: python3-h5py).
"""

import csv
import os
import re
import sys
import xml.etree.ElementTree as ET

try:
    import h5py
    import numpy as np
except ImportError as e:
    print("skipped: %s" % e)
    sys.exit(77)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402


# The units of doc/model.md: x / L, v = D w / (F0 L^2), phi = D psi / (F0 L),
# tau = t / t0, pressure L^2 / F0.
UNITS = {"nodes": "L", "w": "F0*L^2/D", "psi_x": "F0*L/D",
         "psi_y": "F0*L/D", "w_dot": "F0*L^2/(D*t0)",
         "psi_x_dot": "F0*L/(D*t0)", "psi_y_dot": "F0*L/(D*t0)",
         "rotation": "F0*L/D", "displacement": "F0*L^2/D",
         "foundation_pressure": "F0/L^2", "uplift": "F0*L^2/D",
         "contact_status": "1",
         # The moment fields (doc/model.md, "Moments, shear forces and
         # stresses"): moments in F0, shear forces in F0/L, stresses F0/L^2.
         "M_xx": "F0", "M_yy": "F0", "M_xy": "F0", "Q_x": "F0/L",
         "Q_y": "F0/L", "M_1": "F0", "M_2": "F0", "M_1_angle": "degree",
         "sigma_xx": "F0/L^2", "sigma_yy": "F0/L^2", "sigma_xy": "F0/L^2",
         "sigma_max": "F0/L^2"}


def attribute(h5_object, name):
    """An attribute as text or number, None where it is missing."""
    value = h5_object.attrs.get(name)
    return value.decode() if isinstance(value, bytes) else value


def sizes_differing(xdmf, out):
    """The HDF data items of the text `xdmf` whose Dimensions differ from
    the shape of the data set they name, and the number of items."""
    items = [item for item in ET.fromstring(xdmf).iter("DataItem")
             if item.get("Format") == "HDF"]
    differing = []
    for item in items:
        name, path = item.text.strip().split(":")
        with h5py.File(os.path.join(out, name), "r") as h5:
            shape = h5[path].shape
        dimensions = tuple(int(d) for d in item.get("Dimensions").split())
        if dimensions != shape:
            differing.append("%s:%s %s, the file %s"
                             % (name, path, dimensions, shape))
    return differing, len(items)


def main():
    out = sys.argv[1]
    with open(os.path.join(out, "solution.xdmf")) as f:
        xdmf = f.read()
    with open(os.path.join(out, "solution.pvd")) as f:
        pvd_times = [float(t) for t in re.findall(r'timestep="([^"]+)"',
                                                  f.read())]
    times = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', xdmf)]
    files = sorted(set(re.findall(r"(solution_[0-9]+\.h5):/nodes", xdmf)))
    check(len(times) >= 2 and np.allclose(times, pvd_times, rtol=1e-12)
          and len(files) == len(times),
          "solution.xdmf: %d outputs at the times of solution.pvd, one .h5 "
          "each" % len(times))
    differing, n_items = sizes_differing(xdmf, out)
    check(n_items > 0 and not differing,
          "solution.xdmf: %d data items, %d of them with other sizes than "
          "their .h5 %s" % (n_items, len(differing), differing[:2]))
    with open(os.path.join(out, "history.csv")) as f:
        history = {round(float(r["tau"]), 9): float(r["w(0;0)"])
                   for r in csv.DictReader(f)}
    for name, tau in zip(files, times):
        with h5py.File(os.path.join(out, name), "r") as h5:
            nodes = h5["nodes"][:]
            w = h5["w"][:, 0]
            displacement = h5["displacement"][:]
            rotation = h5["rotation"][:]
            psi = np.stack([h5["psi_x"][:, 0], h5["psi_y"][:, 0]], axis=1)
            time, step = attribute(h5, "time"), attribute(h5, "step")
            time_units = attribute(h5, "time_units")
            units = {k: attribute(h5[k], "units") if k in h5 else None
                     for k in UNITS}
            convention = attribute(h5, "moment_sign_convention") or ""
        check(time is not None and abs(time - tau) <= 1e-12 * max(tau, 1)
              and time_units == "t0"
              and step == int(re.search(r"([0-9]+)\.h5", name).group(1)),
              "%s: attributes time = %s (%s), step = %s; solution.xdmf: "
              "tau = %.17g" % (name, time, time_units, step, tau))
        check(units == UNITS, "%s: the units of the data sets %s"
              % (name, units))
        check(convention.startswith("M = int sigma z dz with z along w"),
              "%s: the moments' sign convention as an attribute: '%s'"
              % (name, convention))
        at_origin = np.flatnonzero(np.linalg.norm(nodes[:, :2], axis=1)
                                   < 1e-12)
        probe = history[round(tau, 9)]
        check(len(at_origin) >= 1
              and np.all(np.abs(w[at_origin] - probe)
                         <= 1e-6 * max(abs(probe), 1e-30) + 1e-12),
              "%s (tau = %g): w at (0, 0) is %s, history.csv %.9g"
              % (name, tau, w[at_origin], probe))
        check(np.all(displacement[:, :2] == 0)
              and np.array_equal(displacement[:, 2], w)
              and np.array_equal(rotation[:, :2], psi)
              and np.all(rotation[:, 2] == 0),
              "%s: displacement = (0, 0, w), rotation = (psi_x, psi_y, 0) "
              "at all %d nodes" % (name, len(w)))
        check(nodes.shape[1] == 3 and np.all(nodes[:, 2] == 0)
              and nodes[:, 0].min() == 0 and nodes[:, 0].max() == 0.5
              and nodes[:, 1].min() == 0 and nodes[:, 1].max() == 0.5,
              "%s: the quarter [0, 0.5]^2 at z = 0" % name)
    finish()


if __name__ == "__main__":
    main()
