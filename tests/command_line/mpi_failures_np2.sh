#!/usr/bin/env bash
# Failures on one rank only, on two ranks: every rank must stop with the
# failing rank's message (exit code 1, well within the 60 s that `timeout`
# allows; a hang ends with 124), not wait for ever for the other.
# - rank_0001.bin damaged (one bit of its archive header flipped): the
#   resume is refused naming the file, and no file changes.
# - a directory solution.pvd.tmp in the way of the PVD record, which rank 0
#   alone writes: the run stops naming solution.pvd, the summary says failed.
#   mpi_failures_np2.sh LIFTOFF
set -u
liftoff=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
mpirun=(timeout -k 5 60 "$(command -v mpirun || command -v mpiexec)" --allow-run-as-root --oversubscribe -np 2 "$liftoff")
scene() { # scene DIRECTORY END_TIME
  printf '%s\n' \
    'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 8' \
    '  set Cells along y = 8' 'end' \
    'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
    'subsection Time integration' '  set Time step = 1e-3' "  set End time = $2" 'end' \
    'subsection Output' "  set Directory = $1" '  set VTU interval = 5' \
    '  set Profile points = 3' '  set Profile times = 0.005' 'end' \
    'subsection Checkpoint' '  set Interval = 10' 'end'
}
fingerprint() { (cd "$1" && find . -type f | sort | xargs md5sum); }

scene out 0.01 > first.prm
"${mpirun[@]}" first.prm > /dev/null 2>&1
check $? "the first run on 2 ranks completes"
# Byte 10 lies in boost's archive signature "serialization::archive".
byte=$(od -An -tu1 -j 10 -N1 out/checkpoint/rank_0001.bin | tr -d ' ')
printf "$(printf '\\%03o' $((byte ^ 4)))" | dd of=out/checkpoint/rank_0001.bin bs=1 seek=10 count=1 conv=notrunc status=none
fingerprint out > before.txt
scene out 0.02 > resume.prm
"${mpirun[@]}" --resume resume.prm > stdout.txt 2>&1
status=$?
cat stdout.txt
fingerprint out > after.txt
[ "$status" -eq 1 ] && grep -q 'out/checkpoint/rank_0001.bin is damaged' stdout.txt
check $? "damaged rank_0001.bin: both ranks refuse the resume (exit code $status; 124 = hang)"
cmp -s before.txt after.txt; check $? "damaged rank_0001.bin: no file changed"

mkdir -p pvd/solution.pvd.tmp
scene pvd 0.01 > pvd.prm
"${mpirun[@]}" pvd.prm > stdout.txt 2>&1
status=$?
cat stdout.txt
[ "$status" -eq 1 ] && grep -q 'solution.pvd' stdout.txt && grep -q '^status: failed' pvd/summary.txt
check $? "solution.pvd.tmp in the way: both ranks stop (exit code $status; 124 = hang), the summary says failed"
[ -d pvd/solution.pvd.tmp ]; check $? "solution.pvd.tmp in the way: the user's directory is left alone"
finish
