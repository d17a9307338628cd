#!/usr/bin/env bash
# A damaged checkpoint must be refused, and a refused or killed resume must
# leave the earlier run's files as they were.
# - 25 single-bit flips at fixed pseudo-random places of a finished run's
#   checkpoint (20 in rank_0000.bin, 5 of them in its first 64 bytes, where
#   the archive's header and the first lengths are, and 5 in checkpoint.txt):
#   every resume exits with 1 and a message naming the damaged file, none
#   with a bare std::bad_alloc, and no file of the folder changes.
# - A header of checkpoint format 1 (an older liftoff's) is refused naming
#   the format.
# - SIGKILL at 13 moments of a resume, 4 before it takes the folder over
#   (removes the earlier summary.txt) and 9 from 0 to 200 ms after: either
#   every file is as it was, or the run had a step of its own to write and
#   then the earlier summary is gone and history.csv holds that step. Never
#   header-only CSV files beside the earlier summary.
#   damaged_checkpoint.sh LIFTOFF
set -u
liftoff=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
scene() { # scene END_TIME
  printf '%s\n' \
    'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 16' \
    '  set Cells along y = 16' '  set Polynomial degree = 2' 'end' \
    'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
    'subsection Time integration' '  set Time step = 5e-4' "  set End time = $1" 'end' \
    'subsection Output' '  set Directory = out' '  set VTU interval = 5' \
    '  set Profile points = 5' '  set Profile times = 0.001, 0.004, 0.01' 'end' \
    'subsection Checkpoint' '  set Interval = 10' 'end'
}
fingerprint() { (cd "$1" && find . -type f | sort | xargs md5sum); }
# flip FILE OFFSET BIT: flip one bit of one byte in place.
flip() {
  local byte
  byte=$(od -An -tu1 -j "$2" -N1 "$1" | tr -d ' ')
  printf "$(printf '\\%03o' $((byte ^ (1 << $3))))" |
    dd of="$1" bs=1 seek="$2" count=1 conv=notrunc status=none
}
scene 0.01 > first.prm
timeout -k 5 120 "$liftoff" first.prm > /dev/null 2>&1
check $? "the first run completes"
fingerprint out > before.txt
cp -a out pristine
# restore: the folder as the first run left it.
restore() { rm -rf out; cp -a pristine out; }
scene 0.02 > resume.prm

rank_size=$(stat -c %s out/checkpoint/rank_0000.bin)
header_size=$(stat -c %s out/checkpoint/checkpoint.txt)
refused=0; quiet=0; changed=0
places=$(awk -v r="$rank_size" -v h="$header_size" 'BEGIN {
  srand(11)
  for (k = 0; k < 25; ++k) {
    if (k < 5) print "rank_0000.bin", int(rand() * 64), int(rand() * 8)
    else if (k < 20) print "rank_0000.bin", int(rand() * r), int(rand() * 8)
    else print "checkpoint.txt", int(rand() * h), int(rand() * 8)
  } }')
while read -r name offset bit; do
  flip "out/checkpoint/$name" "$offset" "$bit"
  fingerprint out > damaged.txt
  timeout -k 5 120 "$liftoff" --resume resume.prm > stdout.txt 2>&1
  status=$?
  fingerprint out > after.txt
  if [ "$status" -eq 1 ] && grep -q "out/checkpoint/$name is damaged" stdout.txt &&
     ! grep -q 'bad_alloc' stdout.txt; then
    refused=$((refused + 1))
  else
    echo "  flip of bit $bit at byte $offset of $name: exit code $status, $(tail -1 stdout.txt)"
  fi
  cmp -s damaged.txt after.txt || changed=$((changed + 1))
  restore
done <<< "$places"
[ "$refused" -eq 25 ]; check $? "$refused of 25 single-bit flips refused with a message naming the damaged file"
[ "$changed" -eq 0 ]; check $? "$changed of 25 refused resumes changed a file"
fingerprint out > after.txt
cmp -s before.txt after.txt; check $? "the folder is as the run left it"

sed -i '1s/format [0-9]*/format 1/' out/checkpoint/checkpoint.txt
timeout -k 5 120 "$liftoff" --resume resume.prm > stdout.txt 2>&1
status=$?
[ "$status" -eq 1 ] && grep -q 'is of checkpoint format 1' stdout.txt
check $? "a checkpoint of format 1: refused ($status) naming the format"
restore

# SIGKILL during a resume, at moments tied to when it takes the folder over
# (the earlier summary.txt removed): a loaded machine stretches the start-up
# but not the order of events.
# taken_over PID: wait (polling every 10 ms, at most 60 s) until the run
# PID has taken the folder over or ended.
taken_over() {
  local state
  for _ in $(seq 6000); do
    [ -e out/summary.txt ] || break
    # Bash's own read: no process per poll to compete with the run.
    read -r _ _ state _ < "/proc/$1/stat" 2> /dev/null && [ "$state" != Z ] || break
    sleep 0.01
  done
}
start=$(date +%s.%N)
"$liftoff" --resume resume.prm > /dev/null 2>&1 &
pid=$!
taken_over "$pid"
takeover=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.3f", e - s}')
wait "$pid"
check $? "a resume of the undamaged checkpoint completes (took the folder over after $takeover s)"
restore
bad=0
for k in $(seq 0 12); do
  "$liftoff" --resume resume.prm > /dev/null 2>&1 &
  pid=$!
  # 0, 1/4, 1/2, 3/4 of the time to the take-over, then 0, 25, ..., 200 ms
  # after it.
  if [ "$k" -lt 4 ]; then
    when=$(awk -v t="$takeover" -v k="$k" 'BEGIN {printf "%.3f", k * t / 4}')
    sleep "$when"
    when="$when s"
  else
    taken_over "$pid"
    sleep "$(awk -v k="$k" 'BEGIN {printf "%.3f", (k - 4) * 0.025}')"
    when="$(((k - 4) * 25)) ms after the take-over"
  fi
  kill -KILL "$pid" 2> /dev/null
  wait "$pid" 2> /dev/null
  rm -f out/liftoff.lock
  fingerprint out > after.txt
  rows=$(($(wc -l < out/history.csv) - 1))
  if cmp -s before.txt after.txt; then
    outcome="every file as it was"
  elif [ ! -e out/summary.txt ] && [ "$rows" -gt 21 ]; then
    outcome="taken over: no summary, $rows rows"
  elif grep -q '^status: completed' out/summary.txt && [ "$rows" -eq 41 ]; then
    # An unloaded machine finishes the resume before the later kills.
    outcome="finished before the kill: completed, $rows rows"
  else
    outcome="MIXED: summary $(sed -n 's/^status: //p' out/summary.txt), $rows rows"
    bad=$((bad + 1))
  fi
  echo "  SIGKILL at $when: $outcome"
  restore
done
[ "$bad" -eq 0 ]; check $? "SIGKILL during a resume's start-up: $bad of 13 left a mix of old and new files"
finish
