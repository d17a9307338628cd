#!/usr/bin/env bash
# HDF5 + XDMF output of a run on 2 ranks, read back with h5py by
# hdf5_output.py against the run's .pvd and history.csv. Exit 77 (skipped)
# without h5py.
#   hdf5_output.sh LIFTOFF
set -u
liftoff=$1
checker="$(cd "$(dirname "$0")" && pwd)/hdf5_output.py"
source "$(dirname "$0")/output_checks.sh"
enter_work_directory
/usr/bin/python3 -c 'import h5py' 2>/dev/null || { echo "skipped: no h5py for /usr/bin/python3"; exit 77; }
write_field_scene '  set HDF5 output = true'
mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" scene.prm >stdout.txt 2>stderr.txt
check $? "the run on 2 ranks ends with exit 0"
/usr/bin/python3 "$checker" out
check $? "hdf5_output.py: the HDF5 files hold what the other outputs say"
no_temporary_files out; check $? "no temporary files left"
finish
