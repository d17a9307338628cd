#!/usr/bin/env bash
# Whether two liftoff binaries compute the same results: every scene of
# prm/ is run in full with OLD and then with NEW, and their history.csv
# (and profiles.csv, where the scene writes one) must be byte-identical,
# or (issue 67: a change that makes liftoff faster may move results in
# their last bits) agree in every column to TOLERANCE times the column's
# largest magnitude in OLD's file (benchmarks/column_difference.py; 1e-12
# unless SAME_RESULTS_TOLERANCE says otherwise). It is not a ctest test,
# since it runs the whole scenes.
#
#   benchmarks/same_results.sh OLD_LIFTOFF NEW_LIFTOFF
#
# Each run goes to its own temporary folder (Output/Directory overridden)
# with `VTU interval = 0`, so no VTU files are written: the fields are not
# compared, and writing them would cost most of the time of the longer
# scenes. Everything else of a scene is run as it stands, one rank,
# --quiet. One line per scene; the exit code is 1 if any file differs, is
# missing from one run, or a run fails, 2 on a usage error. The folders of
# a scene that differs are kept and named.
#
# Time: 34 s for the eight scenes of prm/, both binaries one after the
# other (example-2-beam-pulse, 20 000 steps: 3 s per binary), on the
# shared 2-core machine while a -j2 build ran beside it.
set -u
if [ $# -ne 2 ] || [ ! -x "$1" ] || [ ! -x "$2" ]; then
  echo "usage: $0 OLD_LIFTOFF NEW_LIFTOFF (two executable liftoff binaries)" >&2
  exit 2
fi
old=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
new=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
scenes=$(cd "$(dirname "$0")/../prm" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/same_results.XXXXXX")
compared_files="history.csv profiles.csv"
tolerance=${SAME_RESULTS_TOLERANCE:-1e-12}
columns=$(cd "$(dirname "$0")" && pwd)/column_difference.py

# Run `scene` with `binary` into `directory`, quietly; prints the wall
# seconds and returns the binary's exit code.
run_scene() {
  local binary=$1 scene=$2 directory=$3
  local start end status
  start=$(date +%s.%N)
  # Included, not copied, so that files the scene names (a mesh file) are
  # found beside it.
  { printf 'include %s\n' "$scene"
    printf '\nsubsection Output\n  set Directory = %s\n  set VTU interval = 0\nend\n' \
      "$directory"
  } | "$binary" --quiet - >"$directory.log" 2>&1
  status=$?
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN {printf "%.1f", b - a}'
  return $status
}

# Compare the files of the two runs of one scene; prints what differs
# beyond the tolerance (nothing if all agree) and returns 1 if any does;
# sets `nearly` to the files that agree to the tolerance only.
compare_runs() {
  local old_dir=$1 new_dir=$2 file differences=""
  nearly=""
  [ -f "$old_dir/history.csv" ] || differences="no history.csv from OLD;"
  for file in $compared_files; do
    if [ -f "$old_dir/$file" ] && [ -f "$new_dir/$file" ]; then
      if ! cmp -s "$old_dir/$file" "$new_dir/$file"; then
        if within=$(/usr/bin/python3 "$columns" "$old_dir/$file" "$new_dir/$file" "$tolerance"); then
          nearly="$nearly $file $within;"
        else
          differences="$differences $file differs ($within);"
        fi
      fi
    elif [ -f "$old_dir/$file" ] || [ -f "$new_dir/$file" ]; then
      differences="$differences $file written by one run only;"
    fi
  done
  printf '%s' "${differences%;}"
  [ -z "$differences" ]
}

cd "$work" || exit 2
failed=0
start=$(date +%s)
for scene in "$scenes"/*.prm; do
  name=$(basename "$scene" .prm)
  old_seconds=$(run_scene "$old" "$scene" "$work/$name.old"); old_status=$?
  new_seconds=$(run_scene "$new" "$scene" "$work/$name.new"); new_status=$?
  times="old ${old_seconds} s, new ${new_seconds} s"
  if [ $old_status -ne 0 ] || [ $new_status -ne 0 ]; then
    echo "FAILED     $name: exit codes old $old_status, new $new_status ($times; logs in $work)"
    failed=1
  elif compare_runs "$work/$name.old" "$work/$name.new" >/dev/null; then
    rows=$(($(wc -l <"$work/$name.new/history.csv") - 1))
    files=$(cd "$work/$name.new" && ls $compared_files 2>/dev/null | tr '\n' ' ')
    if [ -z "$nearly" ]; then
      echo "identical  $name: ${files}($rows rows; $times)"
    else
      echo "within     $name: ${files}($rows rows; to $tolerance of each column's largest:${nearly%;}; $times)"
    fi
    rm -rf "$work/$name.old" "$work/$name.new" "$work/$name.old.log" "$work/$name.new.log"
  else
    differences=$(compare_runs "$work/$name.old" "$work/$name.new")
    echo "DIFFERENT  $name:$differences (beyond $tolerance of a column's largest; $times; kept in $work)"
    failed=1
  fi
done
echo "$(ls "$scenes"/*.prm | wc -l) scenes in $(($(date +%s) - start)) s"
[ $failed -eq 0 ] && rmdir "$work" 2>/dev/null
exit $failed
