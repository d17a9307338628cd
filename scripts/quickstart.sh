#!/usr/bin/env bash
# Install the dependencies, build liftoff (Release) in build/ and run the
# default scene, the paper's Example 3.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target liftoff
# --overwrite: running the quick start again replaces its earlier results.
./build/liftoff --overwrite prm/example-3-square-plate.prm
echo
echo "Results are in $(pwd)/output-example-3/: solution.pvd (open in ParaView),"
echo "history.csv, profiles.csv, summary.txt, used_parameters.prm."
