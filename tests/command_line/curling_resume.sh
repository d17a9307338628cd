#!/usr/bin/env bash
# A curling scene resumed: prm/si-slab-day-night-truck.prm (a permanent dT,
# a dT(t) that rises, a truck crossing, a tensionless bed) run to t = 0.2 s
# with a checkpoint every 50 steps, then `liftoff --resume` to its end
# (0.6 s), must write the same history.csv, byte for byte, as the run
# straight to 0.6 s. The permanent temperature's start state and the
# vehicle's position come back from the checkpoint, not from a new start.
#   curling_resume.sh LIFTOFF
set -u
liftoff=$1
scene_file="$(cd "$(dirname "$0")/../../prm" && pwd)/si-slab-day-night-truck.prm"
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
scene() { # scene DIRECTORY END_TIME
  cat "$scene_file"
  printf '%s\n' 'subsection Time integration' "  set End time = $2" 'end' \
    'subsection Output' "  set Directory = $1" 'end' \
    'subsection Checkpoint' '  set Interval = 50' 'end'
}
scene out 0.2 > first.prm
"$liftoff" first.prm > first.txt 2>&1
check $? "the run to t = 0.2 s"
scene out 0.6 > resume.prm
"$liftoff" --resume resume.prm > resume.txt 2>&1
check $? "--resume to t = 0.6 s exits with 0"
grep -q '^resumed after step: 100' out/summary.txt
check $? "summary.txt says it resumed after step 100"
scene reference 0.6 > reference.prm
"$liftoff" reference.prm > reference.txt 2>&1
cmp -s reference/history.csv out/history.csv
check $? "history.csv ($(($(wc -l < out/history.csv) - 1)) rows) equals the run without stop"
finish
