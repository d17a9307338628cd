#!/usr/bin/env bash
# The study of doc/studies.md, "A slab lifting off its base": a scene with a
# base the slabs can lift off (by default prm/base-curled-slab-truck.prm, a
# slab curled at night on a cement-treated base, under a truck) against the
# same slabs on the base bonded, unbonded without separation, and on the
# subgrade alone (the k-value method's slab without its base), and with a
# night gradient in the base of its own; the layered run again with half
# the step and with the mesh halved (twice the cells the scene names in each
# direction).
#   bash doc/base/study.sh LIFTOFF OUTPUT [SCENE]
set -euo pipefail
LIFTOFF=$(realpath "$1")
OUT=$2
SCENE=$(realpath "${3:-$(dirname "$0")/../../prm/base-curled-slab-truck.prm}")
entry() { awk -F= -v key="$1" '$1 ~ "set " key " *$" {print $2 + 0}' "$SCENE"; }
STEP=$(entry "Time step")
CELLS_X=$(entry "Cells along x")
CELLS_Y=$(entry "Cells along y")
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
run half-step "subsection Time integration" \
  "  set Time step = $(awk -v s="$STEP" 'BEGIN {print s / 2}')" "end"
run fine-mesh "subsection Discretization" \
  "  set Cells along x = $((2 * CELLS_X))" \
  "  set Cells along y = $((2 * CELLS_Y))" "end"
run bonded "$(base "set Interface = bonded" "set Interface stiffness = 0")"
run unbonded "$(base "set Interface = unbonded" "set Interface stiffness = 0")"
run subgrade "$(base "set Interface = none" "set Thickness = 0" \
  "set Interface stiffness = 0")"
# The base with a night gradient of its own, a quarter of the slab's.
run base-gradient "subsection Loads" "  subsection Temperature load 1" \
  "    set Base profile = 0.25, 0" "  end" "end"
/usr/bin/python3 - <<'PY'
import csv, json
print("run          top [MPa]  at t [s]  bottom [MPa]  base top, bottom [MPa]"
      "  interface contact: rest  min   max  largest dowel force [kN]")
for name in ("tensionless", "half-step", "fine-mesh", "bonded", "unbonded",
             "subgrade", "base-gradient"):
    s = json.load(open(f"{name}/summary.json"))
    top = s["largest tension, top face"]
    bottom = s["largest tension, bottom face"]
    rows = list(csv.DictReader(open(f"{name}/history.csv")))
    key = "interface_contact_fraction"
    fractions = [float(r[key]) for r in rows] if key in rows[0] else []
    contact = (f"{fractions[0]:.3f} {min(fractions):.3f} {max(fractions):.3f}"
               if fractions else "-")
    dowels = [abs(float(r[k])) for r in rows for k in r
              if k.startswith("dowel_")]
    dowel = f"{max(dowels) / 1e3:.2f}" if dowels else "-"
    faces = [s.get(f"largest tension, base {face} face")
             for face in ("top", "bottom")]
    base = " ".join(f"{f['sigma_1 [MPa]']:6.3f}" if f else "     -"
                    for f in faces)
    print(f"{name:12s} {top['sigma_1 [MPa]']:9.3f} {top['time [s]']:9.4f} "
          f"{bottom['sigma_1 [MPa]']:12.3f}  {base}  {contact}  {dowel}")
PY
