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
source "$(dirname "$0")/output_checks.sh"
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

[ "$status" -eq 1 ]; check $? "exit code 1 ($status)"
grep -q 'solution_00020.0000.vtu failed (disk full' stderr.txt; check $? "the message names the file and the cause"
no_temporary_files "$disk"; check $? "no temporary file left"
grep -q '^status: failed' "$disk/out/summary.txt"; check $? "summary.txt says failed"
history_is_complete "$disk/out"
check $? "every row of history.csv has $n_columns columns"
count_vtu_pieces "$disk/out"
[ "$n_pieces" -ge 1 ] && [ "$missing" -eq 0 ]
check $? "the PVD lists $n_pieces complete VTU piece(s), $missing missing or cut short"
finish
