#!/usr/bin/env bash
# Debian 12 packages liftoff needs: deal.II 9.4 (with Trilinos, PETSc, p4est,
# MPI), OpenMPI's launcher, CMake, a compiler, and matplotlib for the plots.
set -euo pipefail
packages=(libdeal.ii-dev openmpi-bin cmake g++ make python3-matplotlib)
if dpkg -s "${packages[@]}" >/dev/null 2>&1; then
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y "${packages[@]}"
