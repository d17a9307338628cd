#!/usr/bin/env bash
# A full disk in the middle of a run, on N_RANKS ranks (1 by default):
# liftoff writes into a small tmpfs that fills
# - while a VTU piece is written (200 kB, fields every 20 steps),
# - while rank 0 alone writes history.csv (64 kB, no fields, no
#   checkpoints, history rows for 2000 steps: about 240 kB), or
# - because another program fills it (dd) once history.csv has been
#   written: the summary must still fit (liftoff holds space back for it).
#   Without that, whether it fits depended on how many rows the first
#   write held, that is on the machine's speed.
# Every rank must stop (exit code 1 within the 60 s `timeout` allows; a
# hang ends with 124) with a message that names the file and the cause,
# leave no temporary file, and keep every file it has complete: the history
# rows, every PVD record's pieces, and a summary that says the run failed.
# Needs root to mount the tmpfs; without it the test is skipped (77).
#   full_disk.sh LIFTOFF [N_RANKS]
set -u
liftoff=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
n_ranks=${2:-1}
source "$(dirname "$0")/../common/output_checks.sh"
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
run=(timeout -k 5 60 "$liftoff")
[ "$n_ranks" -gt 1 ] &&
  run=(timeout -k 5 60 "$(command -v mpirun || command -v mpiexec)" --allow-run-as-root --oversubscribe -np "$n_ranks" "$liftoff")

# fill SIZE WHAT EXPECTED_MESSAGE SCENE_LINES...: run the scene on a fresh
# tmpfs of SIZE and check the outcome.
fill() {
  umount "$disk"
  mount -t tmpfs -o size="$1" tmpfs "$disk"
  printf '%s\n' "${@:4}" > scene.prm
  "${run[@]}" scene.prm >stdout.txt 2>stderr.txt &
  pid=$!
  [ -z "${fill_from_outside:-}" ] || fill_once_history_is_written
  wait "$pid"
  status=$?
  cat stderr.txt
  [ "$status" -eq 1 ]; check $? "$2: exit code 1 ($status; 124 = hang)"
  grep -Eq "$3" stderr.txt; check $? "$2: the message names the file and the cause"
  no_temporary_files "$disk"; check $? "$2: no temporary file left"
  grep -q '^status: failed' "$disk/out/summary.txt"; check $? "$2: summary.txt says failed"
  [ ! -e "$disk/out/history.csv" ] || history_is_complete "$disk/out"
  check $? "$2: every row of history.csv (if any) has ${n_columns:-all} columns"
}
# Another program takes every free block once history.csv is there.
fill_once_history_is_written() {
  while kill -0 "$pid" 2>/dev/null && [ ! -e "$disk/out/history.csv" ]; do
    sleep 0.05
  done
  dd if=/dev/zero of="$disk/filler" bs=4k 2>/dev/null
  echo "filled from outside: $(df -k --output=avail "$disk" | tail -1) KiB left"
}
plate=('subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end')

fill 200k "VTU" 'solution_00020\.000[01]\.vtu failed \(disk full' \
  'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 32' \
  '  set Cells along y = 32' '  set Polynomial degree = 2' 'end' "${plate[@]}" \
  'subsection Time integration' '  set Time step = 5e-4' '  set End time = 0.05' 'end' \
  "subsection Output" "  set Directory = $disk/out" '  set VTU interval = 20' 'end'
count_vtu_pieces "$disk/out"
[ "$n_pieces" -ge "$n_ranks" ] && [ "$missing" -eq 0 ]
check $? "VTU: the PVD lists $n_pieces complete VTU piece(s), $missing missing or cut short"

fill 64k "history.csv" 'history\.csv failed \(disk full' \
  'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 2' \
  '  set Cells along y = 2' 'end' "${plate[@]}" \
  'subsection Time integration' '  set Time step = 1e-4' '  set End time = 0.2' 'end' \
  "subsection Output" "  set Directory = $disk/out" '  set VTU interval = 0' 'end' \
  'subsection Checkpoint' '  set Interval = 0' '  set Wall time interval = 0' 'end'

# A disk without the space for the summary is refused before anything is
# written.
umount "$disk"
mount -t tmpfs -o size=12k tmpfs "$disk"
printf '%s\n' "${plate[@]}" "subsection Output" "  set Directory = $disk/out" 'end' > scene.prm
"${run[@]}" scene.prm >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 1 ] && grep -q 'Output/Directory = .* less than 16 KiB free' stderr.txt &&
  [ -z "$(ls -A "$disk/out")" ]
check $? "a disk with 12 KiB: refused ($status) with a message naming Output/Directory, nothing written"

# About 50 000 steps: far longer than the 1 s before the first write.
fill_from_outside=1
fill 16m "filled from outside" 'history\.csv failed \(disk full' \
  'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 8' \
  '  set Cells along y = 8' '  set Polynomial degree = 2' 'end' "${plate[@]}" \
  'subsection Time integration' '  set Time step = 1e-4' '  set End time = 5' 'end' \
  "subsection Output" "  set Directory = $disk/out" '  set VTU interval = 0' 'end' \
  'subsection Checkpoint' '  set Interval = 0' '  set Wall time interval = 0' 'end'
[ -s "$disk/out/history.csv" ]
check $? "filled from outside: history.csv keeps the rows written before"
finish
