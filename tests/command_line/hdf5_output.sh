#!/usr/bin/env bash
# HDF5 + XDMF output of a run on 2 ranks, read back with h5py by
# hdf5_output.py against the run's .pvd and history.csv. With
# `adaptive-resume` the mesh adapts every 7 steps and the run is resumed
# from its end (tau = 0.06) to tau = 0.1, so that solution.xdmf is rebuilt
# from outputs on other meshes. Exit 77 (skipped) without h5py.
#   hdf5_output.sh LIFTOFF [adaptive-resume]
set -u
liftoff=$1
mode=${2:-}
checker="$(cd "$(dirname "$0")" && pwd)/hdf5_output.py"
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
/usr/bin/python3 -c 'import h5py' 2>/dev/null || { echo "skipped: no h5py for /usr/bin/python3"; exit 77; }
write_field_scene '  set HDF5 output = true'
if [ "$mode" = adaptive-resume ]; then
  printf '%s\n' 'subsection Mesh refinement' '  set Adaptive = true' '  set Interval = 7' \
    '  set Maximum level = 2' 'end' >> scene.prm
fi
mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" scene.prm >stdout.txt 2>stderr.txt
check $? "the run on 2 ranks ends with exit 0"
if [ "$mode" = adaptive-resume ]; then
  sed -i 's/End time = 0.06/End time = 0.1/' scene.prm
  mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" --resume scene.prm >>stdout.txt 2>>stderr.txt
  check $? "its resume to tau = 0.1 ends with exit 0"
fi
/usr/bin/python3 "$checker" out
check $? "hdf5_output.py: the HDF5 files hold what the other outputs say"
no_temporary_files out; check $? "no temporary files left"
finish
