#!/usr/bin/env bash
# A full disk in the middle of a run: liftoff writes into a 200 kB tmpfs,
# which fills while a VTU file is being written. The run must stop with exit
# code 1 and a message that names the file and the cause, leave no
# temporary file, and keep every file it has is complete: the history rows,
# every PVD record's pieces, and a summary that says the run failed.
# Needs root to mount the tmpfs; without it the test is skipped (77).
#   full_disk.sh LIFTOFF
set -u
liftoff=$1
work=$(mktemp -d)
disk="$work/disk"
mkdir -p "$disk"
if ! mount -t tmpfs -o size=200k tmpfs "$disk" 2>/dev/null; then
  echo "SKIP cannot mount a small tmpfs here (needs root)"
  rm -rf "$work"
  exit 77
fi
trap 'umount "$disk"; rm -rf "$work"' EXIT
cd "$work"
printf '%s\n' \
  'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 32' \
  '  set Cells along y = 32' '  set Polynomial degree = 2' 'end' \
  'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
  'subsection Time integration' '  set Time step = 5e-4' '  set End time = 0.05' 'end' \
  "subsection Output" "  set Directory = $disk/out" '  set VTU interval = 20' 'end' > scene.prm
"$liftoff" scene.prm >stdout.txt 2>stderr.txt
status=$?
cat stderr.txt

failures=0
check() { if [ "$1" -eq 0 ]; then echo "PASS $2"; else echo "FAIL $2"; failures=$((failures + 1)); fi; }
[ "$status" -eq 1 ]; check $? "exit code 1 ($status)"
grep -q 'solution_00020.0000.vtu failed (disk full' stderr.txt; check $? "the message names the file and the cause"
[ "$(find "$disk" -name '*.tmp' | wc -l)" -eq 0 ]; check $? "no temporary file left"
grep -q '^status: failed' "$disk/out/summary.txt"; check $? "summary.txt says failed"
n_columns=$(head -1 "$disk/out/history.csv" | awk -F, '{print NF}')
awk -F, -v n="$n_columns" 'NF != n {bad = 1} END {exit bad}' "$disk/out/history.csv"
check $? "every row of history.csv has $n_columns columns"
missing=0
n_pieces=0
for pvtu in $(sed -n 's/.*file="\([^"]*\)".*/\1/p' "$disk/out/solution.pvd"); do
  for piece in $(sed -n 's/.*Source="\([^"]*\)".*/\1/p' "$disk/out/$pvtu"); do
    n_pieces=$((n_pieces + 1))
    tail -c 20 "$disk/out/$piece" | grep -q '</VTKFile>' || missing=$((missing + 1))
  done
done
[ "$n_pieces" -ge 1 ] && [ "$missing" -eq 0 ]
check $? "the PVD lists $n_pieces complete VTU piece(s), $missing missing or cut short"
echo "$((failures == 0 ? 1 : 0)) passed, $((failures == 0 ? 0 : 1)) failed"
[ "$failures" -eq 0 ]
