#!/usr/bin/env bash
# `liftoff --batch` runs several scenes in one process, each into its own
# folder as if run alone: a second method for the same files. Two good
# scenes around a refused one: each good scene's history.csv and
# profiles.csv are byte-identical to its run alone, the refused scene
# names itself in one line and does not stop the scene after it, the batch
# exits 1 and names the scenes that failed; without --batch two scenes are
# refused as before. `liftoff --batch -` (a tool's worker) takes the
# scenes' names from standard input: the same files again, one line per
# scene with its exit code, and its wall time within the worker's, timed
# from outside; the worker's peak memory reset for each scene.
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory

scene() { # NAME MAGNITUDE END_TIME [CELLS]
  printf '%s\n' \
    'subsection Discretization' "  set Cells along x = ${4:-4}" "  set Cells along y = ${4:-4}" 'end' \
    'subsection Loads' '  subsection Point load 1' "    set Magnitude = $2" '  end' 'end' \
    'subsection Time integration' '  set Time step = 0.01' "  set End time = $3" 'end' \
    'subsection Output' "  set Directory = out-$1" '  set VTU interval = 0' \
    '  set Profile points = 5' '  set Profile times = 0.05' 'end' > "$1.prm"
}
# same_as_alone FOLDER WHAT: scenes a and c of FOLDER wrote the files of
# their runs alone.
same_as_alone() {
  for s in a c; do
    for f in history.csv profiles.csv; do
      cmp -s "alone/out-$s/$f" "$1/out-$s/$f"
      check $? "$2, scene $s: $f is the run alone's, byte for byte"
    done
  done
}
mkdir -p alone batch
(cd alone && scene a 1 0.1 && scene c -2 0.08 &&
  "$liftoff" -q a.prm > a.txt 2>&1 && "$liftoff" -q c.prm > c.txt 2>&1)
check $? "the scenes run alone"
(cd batch && scene a 1 0.1 && scene b 1 -0.1 && scene c -2 0.08 &&
  "$liftoff" -q --batch a.prm b.prm c.prm > out.txt 2> err.txt)
status=$?
[ "$status" -eq 1 ]; check $? "a batch with a refused scene exits 1: $status"
same_as_alone batch "batch"
for s in a c; do
  grep -q '^status: completed' "batch/out-$s/summary.txt" 2>/dev/null
  check $? "scene $s completed in the batch"
done
grep -q 'liftoff: error in b.prm' batch/err.txt; check $? "the refused scene names itself"
[ ! -e batch/out-b ]; check $? "the refused scene wrote no folder"
grep -q 'batch: 1 of 3 scenes failed: b.prm' batch/err.txt
check $? "the batch names the scene that failed"
mkdir -p worker
(cd worker && scene a 1 0.1 && scene b 1 -0.1 && scene c -2 0.08 &&
  scene big 1 0.01 160 &&
  start=$(date +%s.%N) &&
  printf '%s\n' big.prm a.prm b.prm c.prm | "$liftoff" -q --batch - > out.txt 2> err.txt
  echo "$? $start $(date +%s.%N)" > status.txt)
read -r status start end < worker/status.txt
[ "$status" -eq 1 ]; check $? "a worker with a refused scene exits 1: $status"
same_as_alone worker "worker"
grep -q '^liftoff: batch: started, cpu [0-9.]* s$' worker/out.txt
check $? "the worker says when it is ready, with its start-up's CPU time"
codes=$(sed -n 's/^liftoff: batch: \(.*\): exit \([0-9]*\), wall .*/\1 \2/p' worker/out.txt | tr '\n' ' ')
[ "$codes" = "big.prm 0 a.prm 0 b.prm 1 c.prm 0 " ]
check $? "one line per scene, in order, with its exit code: $codes"
walls=$(sed -n 's/^liftoff: batch: .*, wall \([0-9.]*\) s, cpu \([0-9.]*\) s$/\1/p' worker/out.txt)
awk -v total="$(echo "$end - $start" | bc)" '{ sum += $1; if ($1 <= 0) bad = 1 }
  END { exit bad || NR != 4 || sum >= total }' <<< "$walls"
check $? "the scenes' wall times are positive and add up to less than the process's, timed from outside: $(echo $walls) against $(echo "$end - $start" | bc) s"
grep -q 'batch: 1 of 4 scenes failed: b.prm' worker/err.txt
check $? "the worker names the scene that failed"
peak() { sed -n 's/^peak memory per rank, max \[MB\]: //p' "$1/summary.txt"; }
big=$(peak worker/out-big) small=$(peak worker/out-c) alone=$(peak alone/out-c)
awk -v big="$big" -v small="$small" -v alone="$alone" \
  'BEGIN { exit !(big > alone + 50 && small < alone + 0.5 * (big - alone)) }'
check $? "the worker's peak memory is each scene's own: c after a larger scene $small MB (alone $alone MB, the larger $big MB)"
(cd batch && "$liftoff" -q a.prm c.prm > two.txt 2>&1)
status=$?
[ "$status" -eq 2 ]; check $? "two scenes without --batch are refused: $status"
finish
