#!/usr/bin/env bash
# SIGINT and SIGTERM stop a run at the end of the current step: the exit
# code is 128 + the signal, the message names the signal and the step, the
# summary says "interrupted", history.csv holds exactly the steps done with
# every row complete, every PVD record's VTU pieces exist and are complete,
# the PVD lists every output (while the run goes it is replaced at most once
# a second, and it was there before the signal), and no temporary file is
# left.
#   interrupt.sh LIFTOFF
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
write_long_scene 7

for signal in INT TERM; do
  rm -rf out
  "$liftoff" scene.prm >stdout.txt 2>stderr.txt &
  pid=$!
  # Let it run past its second output (step 7) until the PVD, replaced at
  # most once a second, lists one.
  wait_for_rows 8
  for _ in $(seq 600); do
    count_vtu_pieces out
    [ "$n_pieces" -ge 1 ] && break
    sleep 0.1
  done
  running_pieces=$n_pieces
  kill -"$signal" "$pid"
  wait "$pid"
  status=$?
  number=$(kill -l "$signal")
  [ "$status" -eq $((128 + number)) ]; check $? "SIG$signal: exit code $status is 128 + $number"
  step=$(sed -n "s/.*Interrupted by signal $number after step \([0-9]*\) .*/\1/p" stderr.txt)
  [ -n "$step" ]; check $? "SIG$signal: the message names the signal and the step ($step)"
  grep -q '^status: interrupted' out/summary.txt 2>/dev/null; check $? "SIG$signal: summary.txt says interrupted"
  rows=$(($(wc -l < out/history.csv) - 1))
  [ "$rows" -eq $((step + 1)) ]; check $? "SIG$signal: history.csv has tau = 0 and the $step steps done: $rows rows"
  history_is_complete out
  check $? "SIG$signal: every row of history.csv has $n_columns columns"
  count_vtu_pieces out
  [ "$n_pieces" -ge 2 ] && [ "$missing" -eq 0 ]
  check $? "SIG$signal: $n_pieces VTU pieces listed, $missing missing or cut short"
  [ "$running_pieces" -ge 1 ] && [ "$n_pieces" -eq $((step / 7 + 1)) ]
  check $? "SIG$signal: the PVD listed $running_pieces outputs while running and lists all $((step / 7 + 1)) at the end: $n_pieces"
  no_temporary_files out; check $? "SIG$signal: no temporary files left"
done
finish
