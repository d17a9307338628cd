#!/usr/bin/env bash
# `liftoff -` reads the scene from standard input, so scripts can generate
# scenes: a generated scene must run and write a history with one row per
# step (End time / Time step = 10 steps, plus tau = 0 and the header),
# profiles at the requested times, the parameters it used, and a summary
# that says it completed.
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
printf '%s\n' \
  'subsection Discretization' '  set Cells along x = 3' '  set Cells along y = 3' 'end' \
  'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
  'subsection Time integration' '  set Time step = 0.01' '  set End time = 0.1' 'end' \
  'subsection Output' '  set Directory = generated' '  set VTU interval = 5' \
  '  set Profile points = 11' '  set Profile times = 0.03, 0.1' 'end' |
  "$liftoff" - >stdout.txt 2>&1
status=$?
[ "$status" -eq 0 ]; check $? "liftoff - exits with 0"
rows=$(wc -l < generated/history.csv 2>/dev/null || echo 0)
[ "$rows" -eq 12 ]; check $? "history.csv has 12 lines (header + 11 steps): $rows"
grep -q 'set End time *= 0.1' generated/used_parameters.prm 2>/dev/null; check $? "used_parameters.prm records the scene"
grep -q '^status: completed' generated/summary.txt 2>/dev/null; check $? "summary.txt says completed"
rows=$(wc -l < generated/profiles.csv 2>/dev/null || echo 0)
[ "$rows" -eq 23 ]; check $? "profiles.csv has 2 profiles of 11 points: $rows lines"
n_vtu=$(grep -c 'DataSet' generated/solution.pvd 2>/dev/null || echo 0)
[ "$n_vtu" -eq 3 ]; check $? "solution.pvd lists steps 0, 5, 10: $n_vtu"
# Every file is complete: each record names existing, finished pieces and
# no temporary file is left behind.
count_vtu_pieces generated
[ "$missing" -eq 0 ] && [ "$n_pieces" -eq 3 ]
check $? "the 3 records' VTU pieces exist and are complete ($n_pieces found, $missing missing or cut short)"
no_temporary_files generated; check $? "no temporary files left"
finish
