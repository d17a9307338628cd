#!/usr/bin/env bash
# Active-set cycling, forced by tests/command_line/active_set_cycle.prm (its
# first step goes round 5 contact sets).
# - Cycle rule none (no detection): the iteration does not settle in 200
#   iterations, so the cycle is real, not a false alarm of the detection.
# - stop: the run ends with exit code 1 and a message naming the cycle and
#   the step.
# - union (the default): the run completes; history.csv reports the cycle
#   length 5 at step 1 and 0 at step 2, summary.txt one cycled step.
# - Two ranks find the same cycle and the same history.
#   active_set_cycle.sh LIFTOFF SCENE
set -u
liftoff=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
scene=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
mpirun=$(command -v mpirun || command -v mpiexec)

run() { # run NAME RANKS RULE
  { cat "$scene"
    printf 'subsection Active set\n  set Cycle rule = %s\nend\n' "$3"
    printf 'subsection Output\n  set Directory = %s\nend\n' "$1"
  } > "$1.prm"
  if [ "$2" -eq 1 ]; then
    "$liftoff" "$1.prm" > "$1.log" 2>&1
  else
    "$mpirun" --allow-run-as-root --oversubscribe -np "$2" "$liftoff" "$1.prm" > "$1.log" 2>&1
  fi
}
# column NAME DIR STEP: the value of a history.csv column at a step.
column() {
  awk -F, -v name="$1" -v row="$(($3 + 2))" '
    NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i }
    NR == row { print $c }' "$2/history.csv"
}

run none 1 none
status=$?
[ $status -eq 1 ]; check $? "none: exit code 1 ($status)"
grep -q 'did not settle in 200 iterations at step 1' none.log
check $? "none: the plain iteration does not settle in 200 iterations"

run stop 1 stop
status=$?
[ $status -eq 1 ]; check $? "stop: exit code 1 ($status)"
grep -q 'went round a cycle of 5 sets at step 1 (tau = 0.022981542)' stop.log
check $? "stop: the message names the cycle of 5 sets and the step"
grep -q '^status: failed' stop/summary.txt; check $? "stop: summary says failed"

run union 1 union
status=$?
[ $status -eq 0 ]; check $? "union: exit code 0 ($status)"
history_is_complete union; check $? "union: complete history rows"
[ "$(column active_set_cycle union 1)" = 5 ]; check $? "union: history reports the cycle of 5 sets at step 1"
[ "$(column active_set_cycle union 2)" = 0 ]; check $? "union: no cycle at step 2"
grep -q '^steps whose active set cycled: 1$' union/summary.txt
check $? "union: summary counts one cycled step"

run union2 2 union
[ $? -eq 0 ]; check $? "union, 2 ranks: exit code 0"
[ "$(column active_set_cycle union2 1)" = 5 ]; check $? "union, 2 ranks: the same cycle of 5 sets"
for name in contact_fraction active_set_iterations; do
  for step in 1 2; do
    value=$(column $name union $step)
    [ -n "$value" ] && [ "$value" = "$(column $name union2 $step)" ]
    check $? "union, 1 vs 2 ranks: the same $name at step $step"
  done
done
finish
