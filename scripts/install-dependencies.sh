#!/usr/bin/env bash
# Debian 12 packages liftoff needs: deal.II 9.4 (with Trilinos, PETSc, p4est,
# MPI, HDF5), MUMPS's parallel C interface (which liftoff calls itself; the
# deal.II package pulls it in only indirectly, through Trilinos Amesos and
# PETSc), OpenBLAS (the dense blocks of the sparse factorisations: a
# factorisation of the benchmark M takes half the time of the reference
# BLAS's; the serial build, so MPI ranks do not compete with BLAS threads
# for the cores), OpenMPI's launcher, CMake, a compiler, nlohmann/json (the
# writer of summary.json), and for the scripts
# numpy, pandas and matplotlib (the study tool, the plots), h5py and meshio
# (the tests of the HDF5 output and of solution.xdmf).
#   scripts/install-dependencies.sh           what the build and tests need
#   scripts/install-dependencies.sh --viewer  also ParaView's pvpython and
#                                             Xvfb for scripts/liftoff-view
#                                             (136 packages on top: 145 MB
#                                             to download, 804 MB on disk,
#                                             85 s of apt on the development
#                                             machine; .ci/run installs them,
#                                             without them liftoff_view and
#                                             xdmf_paraview_np2 are skipped)
set -euo pipefail
packages=(libdeal.ii-dev libmumps-dev libopenblas0-serial openmpi-bin cmake g++ make nlohmann-json3-dev python3-numpy
          python3-pandas python3-matplotlib python3-h5py python3-meshio)
if [ "${1:-}" = "--viewer" ]; then
  packages+=(python3-paraview xvfb)
fi
if dpkg -s "${packages[@]}" >/dev/null 2>&1; then
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y "${packages[@]}"
