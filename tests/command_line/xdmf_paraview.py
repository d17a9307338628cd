"""solution.xdmf opened by ParaView's XDMF3 reader (Xdmf3ReaderT, the one
for time series; Debian 12: python3-paraview 5.11) or its XDMF 2 reader
(XDMFReader), against the run's other outputs. Run by pvpython:

    pvpython xdmf_paraview.py XDMF_FILE OUTPUT_DIRECTORY [XDMFReader]

XDMF_FILE is solution.xdmf named as a user would from the working directory
(a bare name inside the folder, a relative path from elsewhere). The reader
offers one time step per record of OUTPUT_DIRECTORY/solution.pvd, at its
time, and at each w at the node (0, 0) equals history.csv's probe w(0;0)
(to single precision: the fields are stored as float).
"""

import csv
import os
import re
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import MergeBlocks, XDMFReader, Xdmf3ReaderT
from vtk.numpy_interface import dataset_adapter

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
    if sys.argv[3:] == ["XDMFReader"]:
        kind, reader = "XDMFReader", XDMFReader(FileNames=[xdmf])
    else:
        kind, reader = "Xdmf3ReaderT", Xdmf3ReaderT(FileName=[xdmf])
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    check(len(times) == len(pvd_times) >= 2
          and np.allclose(times, pvd_times, rtol=1e-12),
          "%s opens %s from %s: %d time steps at tau = %s (solution.pvd: "
          "%s)" % (kind, xdmf, os.getcwd(), len(times), times, pvd_times))
    merged = MergeBlocks(Input=reader)
    for tau in times:
        merged.UpdatePipeline(tau)
        grid = dataset_adapter.WrapDataObject(servermanager.Fetch(merged))
        points = np.asarray(grid.Points)
        w = np.asarray(grid.PointData["w"]).reshape(-1)
        at_origin = np.flatnonzero(np.linalg.norm(points[:, :2], axis=1)
                                   < 1e-12)
        probe = history[round(tau, 9)]
        check(grid.GetNumberOfCells() > 0 and len(at_origin) >= 1
              and np.all(np.abs(w[at_origin] - probe)
                         <= 1e-6 * max(abs(probe), 1e-30) + 1e-12),
              "tau = %g: %d cells, w at (0, 0) is %s, history.csv %.9g"
              % (tau, grid.GetNumberOfCells(), w[at_origin], probe))
    finish()


if __name__ == "__main__":
    main()
