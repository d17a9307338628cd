#!/usr/bin/env bash
# Install the dependencies, build liftoff (Release) in build/ and run the
# default scene, the paper's Example 3.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target liftoff
./build/liftoff prm/example-3-square-plate.prm
echo
echo "Results are in $(pwd)/output-example-3/: solution.pvd (open in ParaView),"
echo "history.csv, profiles.csv, summary.txt, used_parameters.prm."
