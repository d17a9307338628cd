#!/usr/bin/env bash
# solution.xdmf of a run on 2 ranks read by a reader users have: Debian's
# meshio (its TimeSeriesReader, xdmf_meshio.py) or ParaView's XDMF3 reader
# (xdmf_paraview.py, by pvpython), every step against the run's .pvd and
# history.csv. The output folder is moved first, and the file is opened
# from inside it, from a sibling folder and by its full path from /: the
# .h5 files are looked up beside the .xdmf, not in the working directory
# nor where the run wrote them. Exit 77 (skipped) without the reader.
#   xdmf_readers.sh LIFTOFF meshio|paraview
set -u
liftoff=$1
reader=$2
tests=$(cd "$(dirname "$0")" && pwd)
source "$tests/../common/output_checks.sh"
enter_work_directory
# Inside the folder ParaView is given ./solution.xdmf: its XDMF3 readers
# (5.11) prefix the .h5 names with the .xdmf's path up to its last '/', and
# with a bare name they look for solution.xdmfsolution_00000.h5 and abort;
# no relative name in the file avoids that (doc/viewing.md). Its XDMF 2
# reader, XDMFReader, is given the bare name.
case $reader in
  meshio)
    /usr/bin/python3 -c 'import meshio, h5py' 2>/dev/null \
      || { echo "skipped: no meshio or h5py for /usr/bin/python3 (Debian: python3-meshio)"; exit 77; }
    read_xdmf() { /usr/bin/python3 "$tests/xdmf_meshio.py" "$@"; }
    inside=solution.xdmf ;;
  paraview)
    command -v pvpython >/dev/null || { echo "skipped: no pvpython (Debian: python3-paraview)"; exit 77; }
    read_xdmf() { pvpython "$tests/xdmf_paraview.py" "$@" 2>&1; }
    inside=./solution.xdmf ;;
  *) echo "unknown reader $reader"; exit 2 ;;
esac
write_field_scene '  set HDF5 output = true'
mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" scene.prm >stdout.txt 2>stderr.txt
check $? "the run on 2 ranks ends with exit 0"
mv out moved && mkdir elsewhere
(cd moved && read_xdmf "$inside" .)
check $? "$reader reads $inside from inside the moved folder"
(cd elsewhere && read_xdmf ../moved/solution.xdmf ../moved)
check $? "$reader reads ../moved/solution.xdmf from a sibling folder"
(cd / && read_xdmf "$work/moved/solution.xdmf" "$work/moved")
check $? "$reader reads $work/moved/solution.xdmf from /"
if [ "$reader" = paraview ]; then
  (cd moved && read_xdmf solution.xdmf . XDMFReader)
  check $? "ParaView's XDMFReader reads solution.xdmf from inside the moved folder"
fi
finish
