#!/usr/bin/env bash
# The field files as a viewer reads them: every .vtu piece and .pvtu carries
# TimeValue equal to its time in solution.pvd; the rotation and the
# displacement are 3-component vectors; the fields carry their units; every
# file names the liftoff that wrote it (as --version says); the moment
# fields carry their units and the files their sign convention, and
# `Moment fields = false` leaves them out; and a Q2 mesh of 6 x 6 cells is
# 144 bilinear cells subdivided, 36 cells as higher-order (Lagrange) cells.
#   vtu_fields.sh LIFTOFF
set -u
liftoff=$1
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory
made_by=$("$liftoff" --version | sed 's/^\(liftoff [^ ]* (git [^)]*)\).*/\1/')
for cells in subdivided "higher order"; do
  rm -rf out
  printf '%s\n' \
    'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 6' \
    '  set Cells along y = 6' '  set Polynomial degree = 2' 'end' \
    'subsection Loads' '  subsection Point load 1' '    set Magnitude = 1' '  end' 'end' \
    'subsection Time integration' '  set Time step = 2e-3' '  set End time = 0.02' 'end' \
    'subsection Output' '  set Directory = out' '  set VTU interval = 4' \
    "  set Field cells = $cells" 'end' > scene.prm
  "$liftoff" scene.prm >stdout.txt 2>stderr.txt
  check $? "$cells: the run ends with exit 0"
  n_files=0
  bad_time=0
  for pair in $(sed -n 's/.*timestep="\([^"]*\)".*file="\([^"]*\)".*/\1,\2/p' out/solution.pvd); do
    tau=${pair%%,*}
    pvtu=out/${pair#*,}
    for file in "$pvtu" "${pvtu%.pvtu}".0000.vtu; do
      n_files=$((n_files + 1))
      value=$(sed -n 's/.*Name="TimeValue"[^>]*>\([^<]*\)<.*/\1/p' "$file")
      awk -v a="$value" -v b="$tau" 'BEGIN { exit !(a != "" && (a - b) ^ 2 <= 1e-24) }' || bad_time=$((bad_time + 1))
      grep -q -F -- "<!-- $made_by -->" "$file" || bad_time=$((bad_time + 1))
    done
  done
  [ "$n_files" -eq 8 ] && [ "$bad_time" -eq 0 ]
  check $? "$cells: $n_files files (4 outputs), $bad_time without TimeValue = the .pvd time or '$made_by'"
  pvtu=out/solution_00004.pvtu
  grep -q 'Name="rotation" NumberOfComponents="3"' $pvtu \
    && grep -q 'Name="displacement" NumberOfComponents="3"' $pvtu \
    && grep -q 'Name="w" format="ascii" units="F0\*L^2/D"' $pvtu
  check $? "$cells: rotation and displacement vectors of 3 components, w in F0*L^2/D"
  grep -q 'Name="M_xx" format="ascii" units="F0"' $pvtu \
    && grep -q 'Name="Q_x" format="ascii" units="F0/L"' $pvtu \
    && grep -q 'Name="sigma_max" format="ascii" units="F0/L^2"' $pvtu \
    && grep -q '<!-- moments: M = int sigma z dz' $pvtu \
    && grep -q '<!-- moments: M = int sigma z dz' "${pvtu%.pvtu}".0000.vtu
  check $? "$cells: M_xx in F0, Q_x in F0/L, sigma_max in F0/L^2, the sign convention in .pvtu and .vtu"
  n_cells=$(sed -n 's/.*<Piece NumberOfPoints="[0-9]*" NumberOfCells="\([0-9]*\)".*/\1/p' out/solution_00004.0000.vtu)
  expected=$([ "$cells" = subdivided ] && echo 144 || echo 36)
  [ "$n_cells" = "$expected" ]; check $? "$cells: $n_cells cells in the file, $expected expected"
done
rm -rf out
sed 's/  set VTU interval = 4/&\n  set Moment fields = false/' scene.prm > no_moments.prm
"$liftoff" no_moments.prm >stdout.txt 2>stderr.txt
! grep -q -e 'Name="M_xx"' -e 'moments:' out/solution_00004.pvtu out/solution_00004.0000.vtu \
  && grep -q 'Name="w"' out/solution_00004.pvtu
check $? "Moment fields = false: no moment field and no convention in the files"
finish
