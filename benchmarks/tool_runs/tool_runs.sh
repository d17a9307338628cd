#!/usr/bin/env bash
# What the tools' runs cost end to end: a study, a back-calculation and
# the damage driver, each timed around the whole command (wall seconds),
# so that a process per run and the liftoff workers (`liftoff --batch -`,
# issue 67) can be compared on the same machine.
#
#   benchmarks/tool_runs/tool_runs.sh SCRIPTS LIFTOFF OUTPUT
#
# SCRIPTS: a scripts/ folder (this tree's, or an older commit's taken out
# with `git archive COMMIT scripts | tar -x -C FOLDER`), LIFTOFF the binary
# it runs, OUTPUT a new folder for the results. The commands:
#
# - study: prm/example-1-beam.prm over 10, 20, 40 cells, p = 1, 2 and
#   four time steps (24 runs), --jobs 1;
# - back-calculation: tutorial step 3 (doc/tutorial.md), E, k and c from
#   the deflectometer's histories (44 runs), the histories made first by
#   LIFTOFF;
# - damage: the description of tests/command_line/damage_spectrum.py on
#   24 x 8 cells (damage-spectrum.json, damage-template.prm; 18 runs),
#   --jobs 1.
#
# One line per command: its name, exit code and wall seconds; each one's
# output stays in OUTPUT/NAME.log and its files in OUTPUT/NAME/.
set -u
if [ $# -ne 3 ] || [ ! -d "$1" ] || [ ! -x "$2" ] || [ -e "$3" ]; then
  echo "usage: $0 SCRIPTS LIFTOFF OUTPUT (OUTPUT must not exist)" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
scripts=$(cd "$1" && pwd)
liftoff=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
mkdir -p "$3" && out=$(cd "$3" && pwd)
export PYTHONDONTWRITEBYTECODE=1

timed() { # NAME COMMAND...
  local name=$1 start status
  shift
  start=$(date +%s.%N)
  "$@" >"$out/$name.log" 2>&1
  status=$?
  echo "$name exit $status wall $(echo "$(date +%s.%N) - $start" | bc) s"
}

timed study /usr/bin/python3 "$scripts/liftoff-study" "$root/prm/example-1-beam.prm" \
  --executable "$liftoff" --refine "Discretization/Cells along x=10,20,40" \
  --degrees 1,2 --time-steps 2e-3,1e-3,5e-4,2.5e-4 \
  --set "Time integration/End time=0.1" --set "Output/VTU interval=0" \
  --set "Output/Probe points=0, 0; 0.15, 0" --qoi "w(0;0)" --qoi "w(0.15;0)" \
  --no-plot --output "$out/study"

(cd "$out" && "$liftoff" -q "$root/prm/tutorial-3-deflectometer.prm" >/dev/null) ||
  echo "the deflectometer's histories were not made" >&2
timed backcalc /usr/bin/python3 "$scripts/liftoff-backcalc" \
  --histories "$out/output-tutorial-3-deflectometer/history.csv" \
  --scene "$root/prm/tutorial-3-deflectometer.prm" --thickness 0.25 --poisson 0.15 \
  --executable "$liftoff" --output "$out/backcalc" --no-plot

timed damage /usr/bin/python3 "$scripts/liftoff-damage" "$here/damage-spectrum.json" \
  --executable "$liftoff" --output "$out/damage" --no-plot --jobs 1
