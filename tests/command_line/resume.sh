#!/usr/bin/env bash
# Checkpoints and `liftoff --resume`: a run stopped by SIGINT, and one
# killed (SIGKILL) after a periodic checkpoint, resumed to a later end time,
# must write the same history.csv, profiles.csv and VTU data as one run
# straight to that end time (the VTU and PVD files differ only in the date
# deal.II writes into them). Resumes without a checkpoint, of a changed
# scene, or (on two ranks) on another number of ranks are refused and leave
# the output as it was.
#   resume.sh LIFTOFF [N_RANKS]
set -u
liftoff=$1
n_ranks=${2:-1}
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
if [ "$n_ranks" -gt 1 ]; then
  run=(mpirun --allow-run-as-root --oversubscribe -np "$n_ranks" "$liftoff")
else
  run=("$liftoff")
fi
dt=5e-4
# MUMPS on several ranks differs from run to run in the last bits (its
# dynamic scheduling); KLU factorises on one rank and repeats itself.
solver=()
[ "$n_ranks" -gt 1 ] && solver=('subsection Linear solver' '  set Direct solver package = klu' 'end')
scene() { # scene DIRECTORY END_TIME [EXTRA LINES...]
  printf '%s\n' \
    'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 12' \
    '  set Cells along y = 12' '  set Polynomial degree = 2' 'end' \
    'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
    'subsection Time integration' "  set Time step = $dt" "  set End time = $2" 'end' \
    'subsection Output' "  set Directory = $1" '  set VTU interval = 7' \
    '  set Profile points = 5' '  set Profile times = 0.01, 0.1, 0.2, 0.4, 0.8' 'end' \
    'subsection Checkpoint' '  set Interval = 50' 'end' "${solver[@]}" "${@:3}"
}
# same_results A B: history, profiles, PVD and every VTU piece it lists.
same_results() {
  local bad=0
  cmp -s "$1/history.csv" "$2/history.csv" || bad=1
  cmp -s "$1/profiles.csv" "$2/profiles.csv" || bad=1
  cmp -s <(without_date "$1/solution.pvd") <(without_date "$2/solution.pvd") || bad=1
  same_vtu_pieces "$1" "$2" || bad=1
  return $bad
}
# resume_and_compare LABEL STEP: resume `out` to STEP + 10 steps and compare
# with a run straight there.
resume_and_compare() {
  local end
  end=$(awk -v n="$2" -v dt=$dt 'BEGIN {printf "%.10g", (n + 10) * dt}')
  scene out "$end" > resume.prm
  "${run[@]}" --resume resume.prm > resume_stdout.txt 2>&1
  check $? "$1: --resume to tau = $end exits with 0"
  grep -q '^resumed after step: '"$2" out/summary.txt
  check $? "$1: summary.txt says it resumed after step $2"
  rm -rf reference
  scene reference "$end" > reference.prm
  "${run[@]}" reference.prm > /dev/null 2>&1
  rows=$(($(wc -l < out/history.csv) - 1))
  same_results reference out
  check $? "$1: history.csv ($rows rows), profiles.csv, PVD and VTU data equal a run without stop"
  no_temporary_files out && [ ! -e out/checkpoint.new ]
  check $? "$1: no temporary files or half-written checkpoint left"
}
# start_and_wait: start the long scene in the background, wait until it has
# passed its first periodic checkpoint (step 50) by a few steps. Sets pid.
start_and_wait() {
  scene out 20 > long.prm
  "${run[@]}" long.prm > stdout.txt 2> stderr.txt &
  pid=$!
  wait_for_rows 55
}
# signal_run SIGNAL: signal liftoff itself (under mpirun its processes, which
# are the launcher's children), and wait for the run to end. Sets status.
signal_run() {
  if [ "$n_ranks" -gt 1 ]; then pkill -"$1" -P "$pid" -x liftoff; else kill -"$1" "$pid"; fi
  wait "$pid"
  status=$?
}

# No checkpoint: refused, nothing written.
scene out 0.01 > short.prm
"${run[@]}" --resume short.prm > stdout.txt 2>&1
status=$?
[ "$status" -eq 1 ] && grep -q 'there is no checkpoint in out/checkpoint' stdout.txt && [ ! -e out ]
check $? "no checkpoint: refused with exit code $status, nothing written"

scene out 0.01 'subsection Analysis' '  set Type = static' 'end' > static.prm
"${run[@]}" --resume static.prm > stdout.txt 2>&1
status=$?
[ "$status" -eq 1 ] && grep -q 'Analysis/Type = static has none' stdout.txt && [ ! -e out ]
check $? "static analysis: --resume refused with exit code $status, nothing written"

# SIGINT: a checkpoint of the step the message names.
start_and_wait
signal_run INT
step=$(sed -n 's/.*Interrupted by signal 2 after step \([0-9]*\) .*/\1/p' stderr.txt)
[ "$status" -eq 130 ] && [ -n "$step" ] && grep -q "^step = $step\$" out/checkpoint/checkpoint.txt 2>/dev/null
check $? "SIGINT after step ${step:-?}: exit code $status, checkpoint of that step"

# A changed scene is refused and leaves the files alone.
cp out/history.csv history_before.csv
scene out 20 'subsection Foundation' '  set Stiffness = 2' 'end' > changed.prm
"${run[@]}" --resume changed.prm > stdout.txt 2>&1
status=$?
[ "$status" -eq 1 ] && grep -q 'now <Foundation/Stiffness = 2>' stdout.txt && cmp -s history_before.csv out/history.csv
check $? "changed scene: refused with exit code $status naming Foundation/Stiffness, history.csv untouched"
if [ "$n_ranks" -gt 1 ]; then
  "$liftoff" --resume long.prm > stdout.txt 2>&1
  status=$?
  [ "$status" -eq 1 ] && grep -q "was written by $n_ranks rank(s)" stdout.txt
  check $? "1 rank resuming a $n_ranks-rank checkpoint: refused with exit code $status"
fi
resume_and_compare "SIGINT" "$step"

# SIGKILL after a periodic checkpoint: the rows after it are dropped, and
# temporary files it may have left are removed.
rm -rf out
start_and_wait
wait_for_rows 60
signal_run KILL
# Killed between the renames of a checkpoint, only the previous one is left.
header=out/checkpoint/checkpoint.txt
[ -f "$header" ] || header=out/checkpoint.previous/checkpoint.txt
step=$(sed -n 's/^step = //p' "$header")
rows=$(($(wc -l < out/history.csv) - 1))
[ $((step % 50)) -eq 0 ] && [ "$step" -gt 0 ]
check $? "SIGKILL: the last periodic checkpoint is of step $step (history.csv had $rows rows)"
resume_and_compare "SIGKILL" "$step"

# A results folder moved elsewhere resumes from its new place: the folder
# is the one the scene names now (it was compared as text and refused).
# Raising Active set/Maximum iterations, as its error message advises, is
# allowed as well; the physics is still compared.
mkdir -p moved && mv out moved/out
end=$(awk -v n="$step" -v dt=$dt 'BEGIN {printf "%.10g", (n + 20) * dt}')
scene moved/out "$end" 'subsection Active set' '  set Maximum iterations = 80' 'end' > moved.prm
"${run[@]}" --resume moved.prm > stdout.txt 2>&1
status=$?
[ "$status" -eq 0 ] && grep -q '^resumed after step: ' moved/out/summary.txt
check $? "moved folder, Maximum iterations raised: --resume exits with $status and continues"
scene moved/out "$end" 'subsection Plate' '  set Poisson ratio = 0.25' 'end' > changed_physics.prm
"${run[@]}" --resume changed_physics.prm > stdout.txt 2>&1
status=$?
[ "$status" -eq 1 ] && grep -q 'Plate/Poisson ratio' stdout.txt
check $? "moved folder, Poisson ratio changed: refused with exit code $status naming it"
finish
