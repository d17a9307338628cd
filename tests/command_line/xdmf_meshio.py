#!/usr/bin/python3
"""solution.xdmf read by meshio's TimeSeriesReader (Debian 12: python3-meshio
5.0), against the run's other outputs.

    xdmf_meshio.py XDMF_FILE OUTPUT_DIRECTORY

XDMF_FILE is solution.xdmf named as a user would from the working directory
(a bare name inside the folder, a relative path from elsewhere): the .h5
files it names must be found from there. Every step is read; there is one
per record of OUTPUT_DIRECTORY/solution.pvd, at its time; w at the node
(0, 0) equals history.csv's probe w(0;0) at that time (to single precision:
the fields are stored as float) and the displacement is (0, 0, w) at every
node. Exit 77 without meshio (Debian: python3-meshio).
"""

import csv
import os
import re
import sys

try:
    import meshio
    import numpy as np
except ImportError as e:
    print("skipped: %s" % e)
    sys.exit(77)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from checks import check, finish  # noqa: E402


def main():
    xdmf, out = sys.argv[1], sys.argv[2]
    with open(os.path.join(out, "solution.pvd")) as f:
        pvd_times = [float(t) for t in re.findall(r'timestep="([^"]+)"',
                                                  f.read())]
    with open(os.path.join(out, "history.csv")) as f:
        history = {round(float(r["tau"]), 9): float(r["w(0;0)"])
                   for r in csv.DictReader(f)}
    try:
        with meshio.xdmf.TimeSeriesReader(xdmf) as reader:
            points, cells = reader.read_points_cells()
            steps = [reader.read_data(k) for k in range(reader.num_steps)]
    except Exception as e:  # whatever meshio raises is the failure
        check(False, "meshio %s reads %s: %s: %s"
              % (meshio.__version__, xdmf, type(e).__name__, e))
        finish()
        return
    times = [t for t, _, _ in steps]
    check(len(times) == len(pvd_times) >= 2
          and np.allclose(times, pvd_times, rtol=1e-12),
          "meshio %s reads %s from %s: %d steps at tau = %s (solution.pvd: "
          "%s)" % (meshio.__version__, xdmf, os.getcwd(), len(times),
                   times, pvd_times))
    check(len(cells) == 1 and cells[0].type == "quad"
          and cells[0].data.max() < len(points),
          "%d points, %d quadrilaterals" % (len(points), len(cells[0].data)))
    at_origin = np.flatnonzero(np.linalg.norm(points[:, :2], axis=1) < 1e-12)
    for tau, fields, _ in steps:
        w = fields["w"][:, 0]
        probe = history[round(tau, 9)]
        check(len(at_origin) >= 1
              and np.all(np.abs(w[at_origin] - probe)
                         <= 1e-6 * max(abs(probe), 1e-30) + 1e-12)
              and np.array_equal(fields["displacement"][:, 2], w),
              "tau = %g: w at (0, 0) is %s, history.csv %.9g; displacement "
              "(0, 0, w)" % (tau, w[at_origin], probe))
    finish()


if __name__ == "__main__":
    main()
