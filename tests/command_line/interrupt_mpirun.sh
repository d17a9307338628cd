#!/usr/bin/env bash
# Under mpirun, the way README.md gives to stop a run cleanly: SIGTERM sent
# to the liftoff processes (not to mpirun) ends the run after the current
# step on both ranks, and mpirun's exit code is liftoff's, 128 + 15; the
# message names the signal, summary.txt says interrupted, and --resume
# continues. (mpirun signalled itself kills the ranks about a second later
# and exits 1 whatever they do: README.md.)
#   interrupt_mpirun.sh LIFTOFF
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
write_long_scene 0
mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" scene.prm >stdout.txt 2>stderr.txt &
launcher=$!
# Let both ranks run some steps.
wait_for_rows 5
# The ranks: the children of mpirun that run this liftoff binary.
ranks=$(pgrep -P "$launcher" -f "$(basename "$liftoff") scene.prm")
kill -TERM $ranks
wait "$launcher"
status=$?
[ "$(echo $ranks | wc -w)" -eq 2 ] && [ "$status" -eq 143 ]
check $? "SIGTERM to the 2 ranks ($(echo $ranks)): mpirun exits $status = 128 + 15"
grep -q "Interrupted by signal 15 after step" stderr.txt
check $? "the message names the signal and the step"
grep -q '^status: interrupted' out/summary.txt 2>/dev/null
check $? "summary.txt says interrupted"
end=$(awk -F, 'END { print $1 + 0.005 }' out/history.csv)
sed -i "s/End time = 20/End time = $end/" scene.prm
mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" --resume scene.prm >stdout.txt 2>stderr.txt
check $? "--resume on 2 ranks completes the run"
grep -q '^status: completed' out/summary.txt 2>/dev/null
check $? "summary.txt says completed"
finish
