# Shell helpers shared by the script tests (source this file).

failures=0

# enter_work_directory: make a temporary directory $work, remove it when the
# script exits, and change into it.
enter_work_directory() {
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  cd "$work" || exit 1
}
# check STATUS WHAT: report a check; STATUS 0 is a pass.
check() {
  if [ "$1" -eq 0 ]; then echo "PASS $2"; else echo "FAIL $2"; failures=$((failures + 1)); fi
}

# history_is_complete DIR: every row of DIR/history.csv has as many columns
# as its header. Sets n_columns.
history_is_complete() {
  n_columns=$(head -1 "$1/history.csv" 2>/dev/null | awk -F, '{print NF}')
  [ -n "$n_columns" ] &&
    awk -F, -v n="$n_columns" 'NF != n {bad = 1} END {exit bad}' "$1/history.csv"
}

# count_vtu_pieces DIR: go through the records of DIR/solution.pvd and their
# VTU pieces. Sets n_pieces (pieces listed) and missing (records or pieces
# absent, or pieces not ending in </VTKFile>).
count_vtu_pieces() {
  missing=0
  n_pieces=0
  local pvtu piece
  for pvtu in $(sed -n 's/.*file="\([^"]*\)".*/\1/p' "$1/solution.pvd" 2>/dev/null); do
    [ -f "$1/$pvtu" ] || missing=$((missing + 1))
    for piece in $(sed -n 's/.*Source="\([^"]*\)".*/\1/p' "$1/$pvtu" 2>/dev/null); do
      n_pieces=$((n_pieces + 1))
      tail -c 20 "$1/$piece" 2>/dev/null | grep -q '</VTKFile>' || missing=$((missing + 1))
    done
  done
}

# no_temporary_files DIR: nothing named *.tmp is left below DIR.
no_temporary_files() {
  [ "$(find "$1" -name '*.tmp' | wc -l)" -eq 0 ]
}

# write_long_scene VTU_INTERVAL: scene.prm, a quarter plate (12 x 12 Q2)
# under a point load whose 40 000 steps outlast any test, writing into
# out/ with fields every VTU_INTERVAL steps: a run to be stopped.
write_long_scene() {
  printf '%s\n' \
    'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 12' \
    '  set Cells along y = 12' '  set Polynomial degree = 2' 'end' \
    'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
    'subsection Time integration' '  set Time step = 5e-4' '  set End time = 20' 'end' \
    'subsection Output' '  set Directory = out' "  set VTU interval = $1" 'end' > scene.prm
}

# write_field_scene 'OUTPUT ENTRY': scene.prm, a quarter plate (6 x 6 Q2)
# on a soft foundation under a point load, 30 steps, fields every 10 steps
# into out/, with one more entry of the Output subsection: the fields to
# read back.
write_field_scene() {
  printf '%s\n' \
    'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 6' \
    '  set Cells along y = 6' '  set Polynomial degree = 2' 'end' \
    'subsection Foundation' '  set Stiffness = 1' 'end' \
    'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
    'subsection Time integration' '  set Time step = 2e-3' '  set End time = 0.06' 'end' \
    'subsection Output' '  set Directory = out' '  set VTU interval = 10' \
    "$1" 'end' > scene.prm
}

# finish: print the verdict and return its status.
finish() {
  echo "$((failures == 0 ? 1 : 0)) passed, $((failures == 0 ? 0 : 1)) failed"
  [ "$failures" -eq 0 ]
}
