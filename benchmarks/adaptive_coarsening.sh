#!/usr/bin/env bash
# What coarsening behind the contact front costs on Example 3 (8 x 8 Q2,
# Maximum level 2, Initial refinements 2), doc/adaptivity.md:
#   benchmarks/adaptive_coarsening.sh LIFTOFF FOLDER
# runs the 64 x 64 Q2 reference once, then each coarsening rule, and prints
# per run: the largest error of w(0.15;0) over the run relative to the
# reference's largest value, the dofs (largest, at the end), the wall time
# and the largest relative energy change of one transfer (summary.txt).
set -eu
liftoff=$(realpath "$1")
folder=$2
prm=$(realpath "$(dirname "$0")/../prm/example-3-square-plate.prm")
mkdir -p "$folder"
cd "$folder"

run() { # name, cells, then "Section/Entry = value" lines of Mesh refinement
  local name=$1 cells=$2
  shift 2
  rm -rf "$name"
  mkdir -p "$name"
  {
    echo "include $prm"
    printf 'subsection Discretization\n set Cells along x = %s\n set Cells along y = %s\n set Polynomial degree = 2\nend\n' "$cells" "$cells"
    printf 'subsection Output\n set Directory = %s/out\n set VTU interval = 0\nend\n' "$name"
    echo "subsection Mesh refinement"
    for line in "$@"; do echo " set $line"; done
    echo "end"
  } > "$name/scene.prm"
  /usr/bin/time -f "%e" -o "$name/wall" "$liftoff" "$name/scene.prm" > "$name/log" 2>&1
}

[ -f reference/out/history.csv ] || run reference 64
adaptive=("Adaptive = true" "Maximum level = 2" "Initial refinements = 2")
run uniform 8
run front 8 "${adaptive[@]}" "Indicators = contact front, point loads"
run kelly-coarsens 8 "${adaptive[@]}" "Indicators = kelly, contact front, point loads" \
  "Refine fraction = 0" "Coarsen fraction = 0.3"
run kelly-coarsens-interval-5 8 "${adaptive[@]}" "Indicators = kelly, contact front, point loads" \
  "Refine fraction = 0" "Coarsen fraction = 0.3" "Interval = 5"

/usr/bin/python3 - <<'PY'
import re
import pandas as pd
ref = pd.read_csv("reference/out/history.csv")["w(0.15;0)"]
print(f"{'run':28s} {'error':>9s} {'dofs max':>9s} {'dofs end':>9s} {'wall s':>7s}  energy change")
for name in ["uniform", "front", "kelly-coarsens", "kelly-coarsens-interval-5"]:
    h = pd.read_csv(f"{name}/out/history.csv")
    error = (h["w(0.15;0)"] - ref).abs().max() / ref.abs().max()
    summary = open(f"{name}/out/summary.txt").read()
    jump = re.search(r"largest relative energy change of a transfer:\s*(\S+)", summary)
    wall = open(f"{name}/wall").read().split()[-1]
    print(f"{name:28s} {error:9.3g} {h.dofs.max():9d} {h.dofs.iloc[-1]:9d} {float(wall):7.2f}  "
          + (jump.group(1) if jump else "-"))
PY
