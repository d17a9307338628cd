#!/usr/bin/env bash
# Every scene in prm/ must run as it stands: each is fed to `liftoff -`
# with End time = 5 of its own time steps (or the number its line
# "# prm_scenes: steps = N" gives, for a scene that lifts off later) and no
# VTU files, and must exit
# with 0, say completed, write a history with one complete row per step
# (tau = 0 and 5 steps), only finite numbers, tau advancing by the scene's
# step, and a contact fraction in [0, 1] that is below 1 somewhere (every
# scene loads a plate that lifts off from the tensionless foundation).
set -u
liftoff=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
scenes=$(cd "$2" && pwd)
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
n_scenes=0
for scene in "$scenes"/*.prm; do
  name=$(basename "$scene" .prm)
  n_scenes=$((n_scenes + 1))
  dt=$(sed -n 's/^ *set Time step *= *\([^ #]*\).*/\1/p' "$scene" | tail -1)
  [ -n "$dt" ]; check $? "$name: sets its time step ($dt)"
  steps=$(sed -n 's/^# prm_scenes: steps = \([0-9]*\).*/\1/p' "$scene")
  steps=${steps:-5}
  end=$(awk -v dt="$dt" -v n="$steps" 'BEGIN {printf "%.17g", n * dt}')
  # Included, not copied, so that files the scene names (a mesh file) are
  # found beside it.
  { printf 'include %s\n' "$scene"
    printf '\nsubsection Time integration\n  set End time = %s\nend\n' "$end"
    printf 'subsection Output\n  set Directory = %s\n  set VTU interval = 0\nend\n' "$name"
  } | "$liftoff" - >"$name.log" 2>&1
  [ $? -eq 0 ]; check $? "$name: exits with 0"
  grep -q '^status: completed' "$name/summary.txt" 2>/dev/null; check $? "$name: summary says completed"
  rows=$(wc -l < "$name/history.csv" 2>/dev/null || echo 0)
  [ "$rows" -eq $((steps + 2)) ]; check $? "$name: history.csv has a header and $((steps + 1)) rows: $rows lines"
  history_is_complete "$name"; check $? "$name: every history row has $n_columns columns"
  awk -F, -v dt="$dt" '
    NR == 1 { for (i = 1; i <= NF; ++i) {
                if ($i == "contact_fraction") c = i
                if ($i ~ /^lte/) ratio[i] = 1 }
              next }
    # A load transfer is empty while the load is far from its joint.
    { for (i = 1; i <= NF; ++i)
        if ($i !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ && !(ratio[i] && $i == "")) bad = 1
      if ($c < 0 || $c > 1) bad = 1
      if ($c < 1) lifted = 1
      if (($1 - (NR - 2) * dt)^2 > (1e-9 * dt)^2) bad = 1 }
    END { exit !(c && !bad && lifted) }' "$name/history.csv"
  check $? "$name: finite values (an lte may be empty), tau = k dtau, contact fraction in [0, 1] and below 1 at some step"
done
[ "$n_scenes" -ge 5 ]; check $? "found the scenes of prm/ ($n_scenes)"
finish
