#!/usr/bin/env bash
# The study of doc/studies.md, "A slab lifting off its base": the scene
# prm/base-curled-slab-truck.prm (a slab curled at night on a cement-treated
# base it can lift off, under a truck) against the same slab on the base
# bonded, unbonded without separation, and on the subgrade alone (the
# k-value method's slab without its base); the layered run again with half
# the step and with the mesh halved.
#   bash doc/base/study.sh LIFTOFF OUTPUT
set -euo pipefail
LIFTOFF=$(realpath "$1")
OUT=$2
SCENE=$(realpath "$(dirname "$0")/../../prm/base-curled-slab-truck.prm")
mkdir -p "$OUT"
cd "$OUT"
run() {
  local name=$1
  shift
  {
    echo "include $SCENE"
    printf '%s\n' "$@"
    echo "subsection Output"
    echo "  set Directory = $name"
    echo "  set VTU interval = 0"
    echo "end"
  } > "$name.prm"
  "$LIFTOFF" --overwrite "$name.prm" > "$name.log"
}
base() { echo "subsection Base"; printf '  %s\n' "$@"; echo "end"; }
run tensionless
run half-step "subsection Time integration" "  set Time step = 2.5e-4" "end"
run fine-mesh "subsection Discretization" "  set Cells along x = 36" \
  "  set Cells along y = 24" "end"
run bonded "$(base "set Interface = bonded" "set Interface stiffness = 0")"
run unbonded "$(base "set Interface = unbonded" "set Interface stiffness = 0")"
run subgrade "$(base "set Interface = none" "set Thickness = 0" \
  "set Interface stiffness = 0")"
/usr/bin/python3 - <<'PY'
import csv, json
print("run          top [MPa]  at t [s]  bottom [MPa]  interface contact: rest  min   max")
for name in ("tensionless", "half-step", "fine-mesh", "bonded", "unbonded",
             "subgrade"):
    s = json.load(open(f"{name}/summary.json"))
    top = s["largest tension, top face"]
    bottom = s["largest tension, bottom face"]
    rows = list(csv.DictReader(open(f"{name}/history.csv")))
    key = "interface_contact_fraction"
    fractions = [float(r[key]) for r in rows] if key in rows[0] else []
    contact = (f"{fractions[0]:.3f} {min(fractions):.3f} {max(fractions):.3f}"
               if fractions else "-")
    print(f"{name:12s} {top['sigma_1 [MPa]']:9.3f} {top['time [s]']:9.4f} "
          f"{bottom['sigma_1 [MPa]']:12.3f}  {contact}")
PY
