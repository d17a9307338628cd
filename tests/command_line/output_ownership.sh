#!/usr/bin/env bash
# A run owns its output folder and touches only liftoff's own files in it.
# - A folder holding only the user's files is accepted; the run leaves them
#   alone and removes its lock file when it ends.
# - A second run into a folder with an earlier run's results is refused
#   (exit 1, the message names --overwrite) and changes no file.
# - `--overwrite` replaces the earlier results: none of the earlier run's
#   files is left (its VTU files of later steps included), the user's stay.
# - `--resume` removes the temporary files liftoff left, and only those:
#   the user's *.tmp files, in the folder and in a subfolder, stay.
# - Two runs at once: while one runs, a second run, with or without
#   --overwrite, and a resume are refused naming the first one's pid, and the
#   first run's files stay its own.
# - A run killed with SIGKILL leaves its lock file, which does not block the
#   next run.
#   output_ownership.sh LIFTOFF
set -u
liftoff=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
scene() { # scene DIRECTORY END_TIME [EXTRA LINES...]
  printf '%s\n' \
    'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 4' \
    '  set Cells along y = 4' 'end' \
    'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
    'subsection Time integration' '  set Time step = 1e-3' "  set End time = $2" 'end' \
    'subsection Output' "  set Directory = $1" '  set VTU interval = 5' 'end' \
    'subsection Checkpoint' '  set Interval = 10' 'end' "${@:3}"
}
# fingerprint DIR: every file below DIR with its checksum.
fingerprint() { (cd "$1" && find . -type f | sort | xargs md5sum); }
run() { timeout -k 5 60 "$@" > stdout.txt 2>&1; }

mkdir -p out/sub
echo notes > out/notes.tmp
echo data > out/sub/data.tmp
echo mine > out/mine.txt
fingerprint out > user_files.txt
scene out 0.02 > first.prm
run "$liftoff" first.prm
status=$?
[ "$status" -eq 0 ] && grep -q '^status: completed' out/summary.txt && [ ! -e out/liftoff.lock ]
check $? "a folder with only the user's files: the run completes ($status) and removes its lock file"

fingerprint out > before.txt
scene out 0.01 > second.prm
run "$liftoff" second.prm
status=$?
fingerprint out > after.txt
[ "$status" -eq 1 ] && grep -q 'holds the results of an earlier run' stdout.txt &&
  grep -q -- '--overwrite' stdout.txt && cmp -s before.txt after.txt
check $? "a second run into the folder: refused with exit code $status, no file changed"

run "$liftoff" --overwrite second.prm
status=$?
rows=$(($(wc -l < out/history.csv) - 1))
[ "$status" -eq 0 ] && [ "$rows" -eq 11 ] && [ ! -e out/solution_00015.pvtu ] &&
  [ ! -e out/solution_00020.0000.vtu ] && [ -e out/solution_00010.0000.vtu ] &&
  grep -q '^step = 10$' out/checkpoint/checkpoint.txt
check $? "--overwrite ($status): the new run's $rows rows, no VTU file of the earlier run's steps 15 and 20"
(cd out && md5sum -c --quiet ../user_files.txt)
check $? "--overwrite: the user's files (mine.txt, notes.tmp, sub/data.tmp) are untouched"

# A liftoff temporary file as a killed run leaves it, next to the user's.
echo 'half a row' > out/history.csv.tmp
scene out 0.03 > longer.prm
run "$liftoff" --resume longer.prm
status=$?
[ "$status" -eq 0 ] && [ ! -e out/history.csv.tmp ]
check $? "--resume ($status) removes the history.csv.tmp a killed run left"
(cd out && md5sum -c --quiet ../user_files.txt)
check $? "--resume leaves the user's notes.tmp and sub/data.tmp (and mine.txt) alone"

# Two runs at once.
scene busy 20 > busy.prm
"$liftoff" busy.prm > busy_stdout.txt 2> busy_stderr.txt &
pid=$!
for _ in $(seq 100); do [ -s busy/history.csv ] && break; sleep 0.1; done
scene busy 0.01 > intruder.prm
for start in "" --overwrite --resume; do
  run "$liftoff" $start intruder.prm
  status=$?
  [ "$status" -eq 1 ] && grep -q "another liftoff run (pid $pid on host" stdout.txt
  check $? "while a run writes to the folder, 'liftoff $start' into it is refused ($status) naming pid $pid"
done
kill -INT "$pid"
wait "$pid"
status=$?
rows=$(($(wc -l < busy/history.csv) - 1))
step=$(sed -n 's/.*Interrupted by signal 2 after step \([0-9]*\) .*/\1/p' busy_stderr.txt)
[ "$status" -eq 130 ] && [ "$rows" -eq $((step + 1)) ] && grep -q 'End time *= 20$' busy/used_parameters.prm &&
  grep -q '^status: interrupted' busy/summary.txt
check $? "the first run ends as it would alone ($status, $rows rows, its own used_parameters.prm and summary)"

# A killed run's lock file does not block the next run.
rm -rf busy
"$liftoff" busy.prm > /dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do [ -s busy/checkpoint/checkpoint.txt ] && break; sleep 0.1; done
kill -KILL "$pid"
wait "$pid"
grep -q "pid $pid on host" busy/liftoff.lock
check $? "SIGKILL leaves the lock file naming pid $pid"
header=busy/checkpoint/checkpoint.txt
[ -f "$header" ] || header=busy/checkpoint.previous/checkpoint.txt
step=$(sed -n 's/^step = //p' "$header")
scene busy "$(awk -v n="$step" 'BEGIN {printf "%.10g", (n + 5) * 1e-3}')" > resume_busy.prm
run "$liftoff" --resume resume_busy.prm
status=$?
[ "$status" -eq 0 ] && [ ! -e busy/liftoff.lock ]
check $? "the next run (--resume, $status) is not blocked by it and removes it"
finish
