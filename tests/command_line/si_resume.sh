#!/usr/bin/env bash
# A resume of an SI scene refused in the scene's units: its checkpoint (step
# 10, t = 0.01 s) lies beyond the End time of the resumed scene (0.005 s),
# and the message quotes that End time as written, not in units of t0 (was
# 'End time = 0.080137689', t in units of t0, the dimensionless twin's: the checkpoint was
# opened outside the SI translation).
#   si_resume.sh LIFTOFF
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
scene() { # scene END_TIME
  printf '%s\n' \
    'subsection Units' '  set System = SI' '  set Length = 4' \
    '  set Thickness = 0.25' "  set Young's modulus = 30e9" \
    '  set Density = 2400' '  set Subgrade modulus = 50e6' 'end' \
    'subsection Discretization' '  set Cells along x = 4' \
    '  set Cells along y = 4' 'end' \
    'subsection Time integration' '  set Time step = 1e-3' \
    "  set End time = $1" 'end' \
    'subsection Loads' '  subsection Point load 1' \
    '    set Magnitude = 40e3' '  end' 'end' \
    'subsection Output' '  set Directory = out' '  set VTU interval = 0' 'end' \
    'subsection Checkpoint' '  set Interval = 5' 'end'
}
scene 0.01 > full.prm
"$liftoff" full.prm > stdout.txt 2>&1
check $? "the SI scene runs to t = 0.01 s, a checkpoint after its last step"

scene 0.005 > shorter.prm
cp out/history.csv history_before.csv
"$liftoff" --resume shorter.prm > stdout.txt 2>&1
status=$?
cat stdout.txt
[ "$status" -eq 1 ] \
  && grep -q 'the checkpoint is of step 10, beyond Time integration/End time = <0.005> (5 steps)' stdout.txt \
  && cmp -s history_before.csv out/history.csv
check $? "resume beyond End time: refused with exit code $status, End time in seconds as written, history.csv untouched"
finish
