#!/bin/bash
# doc/studies.md, "A deflectometer test on a curled slab and over a void:
# the dynamic fit": prm/fwd-centre.prm without its corner voids, flat, curled
# by day (+10 K) and at night (-15 K), and over a 0.3 mm paraboloid void
# under the load; each test's sensor histories fitted by
# scripts/liftoff-backcalc --histories over runs of the flat slab
# (flat.prm: the same scene without curl or void, tensionless, with its
# self-weight; no dashpots in either). About 30 runs of 1 s per fit; the
# static fits of the same tests are in doc/studies.md's tables above.
#
#     benchmarks/fwd_dynamic_study.sh build/liftoff FOLDER [NX NY DT]
#
# With NX NY DT every scene, tests and model alike, runs on NX x NY cells
# with the time step DT (the scene's: 9 8 5e-4), for the fits'
# discretisation error.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
liftoff=$(realpath "$1")
mkdir -p "$2" && cd "$2"
centre="$root/prm/fwd-centre.prm"

resolution=""
if [ $# -ge 5 ]; then
  resolution=$(printf 'subsection Discretization\n  set Cells along x = %s\n  set Cells along y = %s\nend\nsubsection Time integration\n  set Time step = %s\nend' "$3" "$4" "$5")
fi
scene() {  # scene NAME TEXT: fwd-centre.prm without its voids, and TEXT
  printf 'include %s\nsubsection Foundation\n  set Initial gap = 0\nend\n%s\n%s\nsubsection Output\n  set Directory = out-%s\nend\n' \
    "$centre" "$2" "$resolution" "$1" > "$1.prm"
}
curling() {
  printf 'subsection Loads\n  subsection Temperature load 1\n    set Magnitude = %s\n    set Expansion coefficient = 1e-5\n    set Permanent = true\n  end\nend\n' "$1"
}
scene flat ""
scene day "$(curling 10)"
scene night "$(curling -15)"
scene void 'subsection Foundation
  set Initial gap = if(x^2 + y^2 < 1, 0.3e-3 * (1 - x^2 - y^2), 0)
end'
common=(--scene flat.prm --thickness 0.25 --poisson 0.15 --executable "$liftoff" --tolerance 1e-4)
fit() {  # fit TEST: the test's run and the dynamic fit of its histories
  "$liftoff" --quiet --overwrite "$1.prm" > /dev/null
  "$root/scripts/liftoff-backcalc" --histories "out-$1/history.csv" \
    "${common[@]}" --output "dynamic-$1" > "dynamic-$1.log"
}
# Two fits side by side: each waits for its liftoff runs.
for pair in "day void" "night flat"; do
  for test in $pair; do fit "$test" & done
  wait
done
for test in day void night flat; do
  echo "== $test"
  cat "dynamic-$test/fit.txt"
done
