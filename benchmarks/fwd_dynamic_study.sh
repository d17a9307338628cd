#!/bin/bash
# doc/studies.md, "A deflectometer test on a curled slab and over a void:
# the dynamic fit": prm/fwd-centre.prm without its corner voids, flat, curled
# by day (+10 K) and at night (-15 K), and over a 0.3 mm paraboloid void
# under the load; each test's sensor histories fitted by
# scripts/liftoff-backcalc --histories over runs of the flat slab
# (fwd-flat.prm: the same scene without curl or void, tensionless, with its
# self-weight), and each peak basin statically over fwd-centre-static.prm
# (doc/deflectometer.md). About 30 runs of 1 s per dynamic fit.
#
#     benchmarks/fwd_dynamic_study.sh build/liftoff FOLDER
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
liftoff=$(realpath "$1")
mkdir -p "$2" && cd "$2"
centre="$root/prm/fwd-centre.prm"

scene() {  # scene NAME TEXT: fwd-centre.prm without its voids, and TEXT
  printf 'include %s\nsubsection Foundation\n  set Initial gap = 0\nend\n%s\nsubsection Output\n  set Directory = out-%s\nend\n' \
    "$centre" "$2" "$1" > "$1.prm"
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
cat > static.prm <<STATIC
include $centre
subsection Analysis
  set Type = static
end
subsection Units
  set Gravity = 0
end
subsection Foundation
  set Model       = bilateral
  set Initial gap = 0
end
subsection Loads
  subsection Deflectometer 1
    set Pulse shape = constant
  end
end
STATIC

common=(--scene flat.prm --thickness 0.25 --poisson 0.15 --executable "$liftoff" --no-plot)
for test in flat day night void; do
  "$liftoff" --quiet --overwrite "$test.prm" > /dev/null
  "$root/scripts/liftoff-backcalc" --histories "out-$test/history.csv" \
    "${common[@]}" --output "dynamic-$test" --tolerance 1e-6 > "dynamic-$test.log"
  "$root/scripts/liftoff-backcalc" "out-$test/basin.csv" --scene static.prm \
    --thickness 0.25 --poisson 0.15 --executable "$liftoff" --no-plot \
    --output "static-$test" --tolerance 1e-6 > "static-$test.log"
  echo "== $test"
  grep -h -A20 "^start:" "static-$test/fit.txt" "dynamic-$test/fit.txt"
done
