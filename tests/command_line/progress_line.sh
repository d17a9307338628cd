#!/usr/bin/env bash
# The progress line of a run into a file (not a terminal): one line per
# update, at most one a second, and always one for the last step, naming
# the step against the number of steps the scene asks for (End time /
# Time step, computed here), tau, iterations, contact and the time so far;
# --quiet (also -q, before or after --overwrite) leaves it out and prints
# one status line instead of the summary (which stays in summary.txt); on
# 2 ranks the run completes with one line per update. The
# fec74b2 binary prints no progress line and refuses --quiet.
#   progress_line.sh LIFTOFF
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory

cat > scene.prm <<'PRM'
subsection Discretization
  set Cells along x = 4
  set Cells along y = 4
end
subsection Loads
  subsection Pressure 1
    set Magnitude = 1
  end
end
subsection Time integration
  set Time step = 0.01
  set End time = 0.25
end
subsection Output
  set Directory = out
  set VTU interval = 0
end
PRM
n_steps=$(awk 'BEGIN { printf "%d", 0.25 / 0.01 + 0.5 }')

"$liftoff" scene.prm > stdout.txt 2>&1
status=$?
last=$(grep '^step ' stdout.txt | tail -1)
[ "$status" -eq 0 ] && echo "$last" | grep -q "^step $n_steps/$n_steps  tau 0.25  iterations [0-9]*  contact [01]\.[0-9]*  elapsed [0-9.]* s$"
check $? "the last step's line: <$last>"
lines=$(grep -c '^step ' stdout.txt)
seconds=$(sed -n 's/^wall time \[s\]: //p' out/summary.txt)
awk -v n="$lines" -v s="$seconds" 'BEGIN { exit !(n >= 1 && n <= s + 2) }'
check $? "$lines progress lines in $seconds s: at most one a second and the last"
! grep -q $'\r' stdout.txt
check $? "no carriage return outside a terminal"

# Rank 0 alone writes the line, and only from what every rank computed:
# a collective call made on rank 0 alone (as the first version did for the
# contact fraction) mismatches the ranks' MPI calls.
mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" --overwrite scene.prm > mpi.txt 2>&1
status=$?
[ "$status" -eq 0 ] && [ "$(grep -c "^step $n_steps/$n_steps " mpi.txt)" -eq 1 ] && grep -q '^status: completed' out/summary.txt
check $? "2 ranks: exit $status, one last-step line, completed"

for options in "--quiet --overwrite" "--overwrite -q"; do
  # shellcheck disable=SC2086
  "$liftoff" $options scene.prm > quiet.txt 2>&1
  status=$?
  [ "$status" -eq 0 ] && ! grep -q '^step ' quiet.txt && grep -q '^status: completed; summary in out/summary.txt$' quiet.txt \
    && [ "$(grep -vc '^liftoff: ' quiet.txt)" -le 1 ] && grep -q '^wall time' out/summary.txt
  check $? "$options: exit $status, no progress line, one status line ($(wc -l < quiet.txt) lines), the summary in summary.txt"
done
finish
