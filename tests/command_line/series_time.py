"""pvpython: the .pvtu files of a run opened as a series, without the .pvd;
prints the times ParaView gives them (from TimeValue), one line.
    pvpython series_time.py OUTPUT_DIRECTORY"""
import glob
import sys

import paraview.simple as pv

reader = pv.OpenDataFile(sorted(glob.glob(sys.argv[1] + "/solution_*.pvtu")))
print(" ".join("%.17g" % t for t in reader.TimestepValues))
