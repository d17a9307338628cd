#!/usr/bin/env bash
# A warning of an SI scene's run in the scene's units: the stiff bed of
# tests/bad_input/si_energy_balance_stiff_bed.prm with Energy check/Mode =
# warn (the default) completes, and its energy warning, on standard error
# and in summary.txt, gives the time in seconds and the Time step as
# written (was 'Step 2 (tau = 0.00096165227): ... Time step =
# 0.00048082614', the dimensionless twin's: the time stepper wrote its
# warnings outside the SI translation), and the energies in J and the
# bed's frequency in rad/s (were the twin's F0^2 L^2 / D and 1/t0).
#   si_energy_warning.sh LIFTOFF
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
sed -e 's/set Mode = fail/set Mode = warn/' \
  "$(dirname "$0")/../bad_input/si_energy_balance_stiff_bed.prm" > warn.prm
"$liftoff" warn.prm > stdout.txt 2> stderr.txt
status=$?
cat stderr.txt
expected='Step 2 (t = 6e-05 s): the energy balance error at step 2 ([0-9.e-]* J) is .* energy scale [0-9.e+]* J, .* Time integration/Time step = <3e-5> is long for the bed: the plate swings on it at omega = sqrt(k / (rho H)) = 158113.88 rad/s'
[ "$status" -eq 0 ] && grep -q "^liftoff: warning: $expected" stderr.txt
check $? "exit code $status, the warning on standard error in seconds and as written"
grep -q '^status: completed with warnings' out/summary.txt && grep -q "$expected" out/summary.txt
check $? "summary.txt: completed with warnings, the same warning"
finish
