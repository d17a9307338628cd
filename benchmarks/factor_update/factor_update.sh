#!/usr/bin/env bash
# Issue 36: would a factor kept current by low-rank updates (CHOLMOD's
# cholmod_updown with the springs that changed) beat today's stale factor
# and CG? Measures, on S (whole run) and M (first 20 steps):
#  - how many Gauss points change contact status per step, and
#  - what a rank-k update of the factor costs against a factorisation and a
#    substitution on the scene's own matrix,
# and writes factor_update.md beside this script.
#
#   benchmarks/factor_update/factor_update.sh [COMMIT]   (default HEAD)
#
# The counts and the matrix come from a throw-away build of COMMIT with
# instrument.patch applied (two hooks behind environment variables, not in
# liftoff: LIFTOFF_COUNT_CHANGES prints each contact update's number of
# changed points, LIFTOFF_DUMP_MATRIX writes the first factorised matrix in
# Matrix Market form). The build uses ccache when it is installed. Time:
# about 3 min, plus the build (8 min on 2 cores with a cold ccache).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
commit=${1:-HEAD}
work=$(mktemp -d "${TMPDIR:-/tmp}/factor_update.XXXXXX")
trap 'git -C "$repo" worktree remove --force "$work/src" >/dev/null 2>&1 || true' EXIT

git -C "$repo" worktree add --detach -q "$work/src" "$commit"
git -C "$work/src" apply "$here/instrument.patch"
launcher=()
if command -v ccache >/dev/null; then
  # Paths relative to the worktree, so that a second run hits the cache.
  export CCACHE_BASEDIR=$work CCACHE_NOHASHDIR=1
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build "$work/build" -j2 --target liftoff >/dev/null
g++ -O2 -o "$work/cost" "$here/factor_update_cost.cc" -I/usr/include/suitesparse -lcholmod

# run NAME SCENE [END_TIME]: the changes per step after the first, printed.
run() {
  local name=$1 scene=$2 end_time=${3:-}
  { cat "$scene"
    printf '\nsubsection Output\n  set Directory = %s\n  set VTU interval = 0\nend\n' "$work/$name"
    if [ -n "$end_time" ]; then
      printf 'subsection Time integration\n  set End time = %s\nend\n' "$end_time"
    fi
  } > "$work/$name.prm"
  LIFTOFF_COUNT_CHANGES=1 LIFTOFF_DUMP_MATRIX="$work/$name.mtx" \
    "$work/build/liftoff" --quiet "$work/$name.prm" > "$work/$name.log" 2> "$work/$name.changes"
  local steps
  steps=$(sed -n 's/^steps: //p' "$work/$name/summary.txt")
  awk -v steps="$steps" '/^CHANGES/ { if (first == "") first = $2; else { s += $2; c += $3 } }
    END { printf "%d %d %.0f %.0f\n", steps, first, s / steps, c / steps }' "$work/$name.changes"
}

report="$here/factor_update.md"
{
  echo "# A factor kept current by rank-k updates"
  echo
  echo "\`benchmarks/factor_update/factor_update.sh $commit\` ($(git -C "$repo" rev-parse --short "$commit")), $(date -u +%Y-%m-%d), load average $(cut -d' ' -f1 /proc/loadavg) at the start."
  echo
  for scene in S:S-gamma1: M:M-gamma1:0.01; do
    IFS=: read -r name file end_time <<< "$scene"
    read -r steps first per_step cells <<< "$(run "$name" "$repo/benchmarks/scenes/$file.prm" "$end_time")"
    echo "## $name ($steps steps)"
    echo
    echo "Points whose contact status changed: $first at the first update (the start from full contact), then $per_step per step (in $cells cells per step)."
    echo "liftoff's own substitution in that run: $(sed -n 's/^time per substitution \[s\]: //p' "$work/$name/summary.txt") s; substitutions per step: $(awk -v s="$steps" '/^substitutions:/ {printf "%.2f", $2 / s}' "$work/$name/summary.txt")."
    echo
    echo '```'
    "$work/cost" "$work/$name.mtx" 1 8 "$per_step"
    echo '```'
    echo
  done
} | tee "$report"
