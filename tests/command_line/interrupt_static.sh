#!/usr/bin/env bash
# SIGINT during a static analysis stops it like a dynamic run: exit code
# 130, a message naming the signal, `status: interrupted` in the summary and
# no result row. (It used to be ignored: exit 0, status completed.) The
# scene is large enough (full 100 x 100 Q2, about 120 000 unknowns)
# that the signal, sent when the output folder appears (after assembly),
# arrives during the factorisation and solve.
#   interrupt_static.sh LIFTOFF
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
printf '%s\n' \
  'subsection Analysis' '  set Type = static' 'end' \
  'subsection Discretization' '  set Cells along x = 100' \
  '  set Cells along y = 100' '  set Polynomial degree = 2' 'end' \
  'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
  'subsection Output' '  set Directory = out' 'end' > scene.prm

"$liftoff" scene.prm >stdout.txt 2>stderr.txt &
pid=$!
for _ in $(seq 600); do [ -s out/used_parameters.prm ] && break; sleep 0.1; done
kill -INT "$pid"
wait "$pid"
status=$?
cat stderr.txt
[ "$status" -eq 130 ]; check $? "exit code $status is 128 + 2"
grep -q 'Interrupted by signal 2 during the static analysis' stderr.txt
check $? "the message names the signal and the static analysis"
grep -q '^status: interrupted' out/summary.txt 2>/dev/null; check $? "summary.txt says interrupted"
rows=$(($(wc -l < out/history.csv) - 1))
[ "$rows" -eq 0 ]; check $? "history.csv holds no result row ($rows)"
no_temporary_files out; check $? "no temporary files left"
finish
