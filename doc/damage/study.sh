#!/bin/bash
# The first damage study of doc/damage.md: the jointed scene under one
# 120 kN single axle at night, flat and by day, dynamic and static,
# tensionless and bilateral, and the discretisation's share (the time step,
# the mesh and the static positions' spacing halved).
#     bash doc/damage/study.sh LIFTOFF OUTPUT_FOLDER
set -e
liftoff=$1
out=$2
tool="nice -n 10 /usr/bin/python3 scripts/liftoff-damage"
fine=(--set "Discretization/Cells along x=108" --set "Discretization/Cells along y=30")
bilateral=(--set "Foundation/Model=bilateral")
run() {
  local name=$1; shift
  local start=$(date +%s)
  $tool "$@" --executable "$liftoff" --output "$out/$name" --jobs 2 --reuse --no-plot > "$out/$name.log" 2>&1
  echo "$name: $(( $(date +%s) - start )) s" | tee -a "$out/times.txt"
}
mkdir -p "$out"
run dynamic doc/damage/study.json
run static doc/damage/study.json --static
run dynamic-bilateral doc/damage/study.json "${bilateral[@]}"
run static-bilateral doc/damage/study.json --static "${bilateral[@]}"
run dynamic-half-step doc/damage/study-half-step.json
run static-half-spacing doc/damage/study-half-spacing.json --static
run dynamic-fine doc/damage/study.json "${fine[@]}"
run static-fine doc/damage/study.json --static "${fine[@]}"
