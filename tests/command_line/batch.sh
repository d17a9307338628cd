#!/usr/bin/env bash
# `liftoff --batch` runs several scenes in one process, each into its own
# folder as if run alone: a second method for the same files. Two good
# scenes around a refused one: each good scene's history.csv and
# profiles.csv are byte-identical to its run alone, the refused scene
# names itself in one line and does not stop the scene after it, the batch
# exits 1 and names the scenes that failed; without --batch two scenes are
# refused as before.
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory

scene() { # NAME MAGNITUDE END_TIME
  printf '%s\n' \
    'subsection Discretization' '  set Cells along x = 4' '  set Cells along y = 4' 'end' \
    'subsection Loads' '  subsection Point load 1' "    set Magnitude = $2" '  end' 'end' \
    'subsection Time integration' '  set Time step = 0.01' "  set End time = $3" 'end' \
    'subsection Output' "  set Directory = out-$1" '  set VTU interval = 0' \
    '  set Profile points = 5' '  set Profile times = 0.05' 'end' > "$1.prm"
}
mkdir -p alone batch
(cd alone && scene a 1 0.1 && scene c -2 0.08 &&
  "$liftoff" -q a.prm > a.txt 2>&1 && "$liftoff" -q c.prm > c.txt 2>&1)
check $? "the scenes run alone"
(cd batch && scene a 1 0.1 && scene b 1 -0.1 && scene c -2 0.08 &&
  "$liftoff" -q --batch a.prm b.prm c.prm > out.txt 2> err.txt)
status=$?
[ "$status" -eq 1 ]; check $? "a batch with a refused scene exits 1: $status"
for s in a c; do
  for f in history.csv profiles.csv; do
    cmp -s "alone/out-$s/$f" "batch/out-$s/$f"
    check $? "scene $s: $f of the batch is the run alone's, byte for byte"
  done
  grep -q '^status: completed' "batch/out-$s/summary.txt" 2>/dev/null
  check $? "scene $s completed in the batch"
done
grep -q 'liftoff: error in b.prm' batch/err.txt; check $? "the refused scene names itself"
[ ! -e batch/out-b ]; check $? "the refused scene wrote no folder"
grep -q 'batch: 1 of 3 scenes failed: b.prm' batch/err.txt
check $? "the batch names the scene that failed"
(cd batch && "$liftoff" -q a.prm c.prm > two.txt 2>&1)
status=$?
[ "$status" -eq 2 ]; check $? "two scenes without --batch are refused: $status"
finish
