#!/usr/bin/env bash
# Run liftoff on a scene that must be refused and check that it is, cleanly:
#   expect_failure.sh LIFTOFF SCENE.prm
# The scene's first line is "# EXPECT: <extended regex>" that the error
# message must match. The scene writes to Output/Directory = out. Unless the
# scene has a line "# OUTPUT: kept" (a run that fails midway), no output
# folder may be left behind; with it, the folder must hold a summary that
# says the run failed and a history whose every row is complete.
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
scene=$2
expect=$(sed -n '1s/^# EXPECT: //p' "$scene")
[ -n "$expect" ] || { echo "FAIL $scene has no '# EXPECT:' first line"; exit 1; }

enter_work_directory
"$liftoff" "$scene" >stdout.txt 2>stderr.txt
status=$?
cat stderr.txt

[ "$status" -ne 0 ]; check $? "exit code is non-zero ($status)"
grep -Eq -- "$expect" stderr.txt; check $? "message matches /$expect/"
if grep -q '^# OUTPUT: kept' "$scene"; then
  grep -q '^status: failed' out/summary.txt 2>/dev/null; check $? "summary.txt says the run failed"
  history_is_complete out
  check $? "every row of history.csv has $n_columns columns"
else
  [ ! -e out ]; check $? "no output folder was created"
fi
finish
