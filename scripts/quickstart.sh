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
scripts/liftoff-history output-example-3
echo
echo "Results are in $(pwd)/output-example-3/: solution.pvd (open in ParaView),"
echo "history.csv (plotted in history.png), profiles.csv, summary.txt,"
echo "used_parameters.prm. Pictures of the standard view: scripts/liftoff-view"
echo "output-example-3 (needs scripts/install-dependencies.sh --viewer)."
