#!/usr/bin/env bash
# scripts/liftoff-view on a quarter model written as higher-order cells: one
# picture per output time of solution.pvd, each a PNG and each different;
# the plate drawn whole (reflected: x and y from -0.5 to 0.5); the warp of
# the right sign and size: the lowest point drawn is -scale * w at the
# centre, w from history.csv's probe w(0;0) (w > 0 is into the foundation,
# drawn downwards), by the displacement vector of the files. And the .pvtu
# files opened as a series, without the .pvd, carry the times of the .pvd.
# --field Q_x gets the reflection's sign on the mirrored parts, and an unknown
# field is refused by name. Exit 77 (skipped) where pvpython or Xvfb is missing.
#   liftoff_view.sh LIFTOFF SCRIPTS_DIR
set -u
liftoff=$1
scripts=$(cd "$2" && pwd)
tests=$(cd "$(dirname "$0")" && pwd)
source "$tests/../common/output_checks.sh"
enter_work_directory
command -v pvpython >/dev/null && { [ -n "${DISPLAY:-}" ] || command -v Xvfb >/dev/null; } \
  || { echo "skipped: no pvpython or Xvfb (Debian: python3-paraview xvfb)"; exit 77; }
write_field_scene '  set Field cells = higher order'
"$liftoff" scene.prm >stdout.txt 2>stderr.txt
check $? "the run ends with exit 0"
"$scripts/liftoff-view" out --size 400,300 >view.txt 2>view-stderr.txt
status=$?
cat view.txt
# What went wrong, for a failure seen only under load.
[ "$status" -eq 0 ] || cat view-stderr.txt
[ "$status" -eq 0 ] && grep -q "4 picture(s) in out/pictures, warped by displacement" view.txt
check $? "liftoff-view: exit $status, 4 pictures, warped by the displacement vector"
pvd_times=$(sed -n 's/.*timestep="\([^"]*\)".*/\1/p' out/solution.pvd | tr '\n' ' ')
n_png=0; n_distinct=$(md5sum out/pictures/view_*.png 2>/dev/null | cut -d' ' -f1 | sort -u | wc -l)
for png in out/pictures/view_*.png; do
  [ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] && n_png=$((n_png + 1))
done
[ "$n_png" -eq 4 ] && [ "$n_distinct" -eq 4 ]
check $? "$n_png PNG pictures, $n_distinct different, for the times $pvd_times"
# view.csv: picture,tau,max_w,x_min,x_max,y_min,y_max,z_min,z_max
bad=$(awk -F, -v history=out/history.csv '
  BEGIN { while ((getline line < history) > 0) { split(line, f, ","); w[f[1] + 0] = f[2] } }
  NR == 1 { next }
  { probe = w[$2 + 0]; n += 1
    if ($4 != -0.5 || $5 != 0.5 || $6 != -0.5 || $7 != 0.5) { print "bounds " $0; next }
    if (($3 - probe) ^ 2 > (1e-6 * probe) ^ 2 + 1e-24) { print "max w " $3 " probe " probe; next }
    if (NR == 2) next
    if (probe > 0) { s = -$8 / probe; if (last != "" && (s - last) ^ 2 > (1e-5 * s) ^ 2) print "scale " s " " last; last = s
                     if (s <= 0) print "sign " $0 } }
  END { if (n != 4) print "rows " n }' out/pictures/view.csv)
[ -s out/pictures/view.csv ] && [ -z "$bad" ]; check $? "view.csv: whole plate, max w = w(0;0) of history.csv, lowest point -scale w(0;0) with one scale > 0 ${bad:+($bad)}"
# --field Q_x: odd in x, so the reflected half carries the negative values;
# drawn whole, its range is symmetric about 0 (without the reflection's sign
# both halves would show the modelled part's values).
"$scripts/liftoff-view" out --size 400,300 --field Q_x --pictures out/q >/dev/null 2>q-stderr.txt
status=$?
range=$(tail -1 out/q/view.csv 2>/dev/null | awk -F, '{ print $10, $11 }')
odd=$(echo "$range" | awk '{ print ($2 > 0 && ($1 + $2) ^ 2 <= (1e-6 * $2) ^ 2) }')
[ "$status" -eq 0 ] && [ "$odd" = 1 ]
check $? "liftoff-view --field Q_x: exit $status, range on the whole plate $range symmetric about 0"
"$scripts/liftoff-view" out --field M_zz --pictures out/none >/dev/null 2>bad-field.txt
status=$?
[ "$status" -ne 0 ] && grep -q "field M_zz: the files have no such field" bad-field.txt
check $? "liftoff-view --field M_zz: exit $status and $(head -c 120 bad-field.txt)"
# A scene in SI units (a 5 m slab): the files are in metres, so the whole
# plate spans -2.5 to 2.5 m and the default scale draws the largest w as
# 0.15 of its length, 0.75 m; the colour bar's unit is an engineer's (kN m/m).
printf '%s\n' 'subsection Units' '  set System = SI' '  set Length = 5' '  set Thickness = 0.25' \
  "  set Young's modulus = 30e9" '  set Density = 2400' '  set Subgrade modulus = 50e6' 'end' \
  'subsection Discretization' '  set Symmetry = quarter' '  set Cells along x = 4' '  set Cells along y = 4' 'end' \
  'subsection Loads' '  subsection Point load 1' '    set Magnitude = 50e3' '  end' 'end' \
  'subsection Time integration' '  set Time step = 2e-4' '  set End time = 2e-3' 'end' \
  'subsection Output' '  set Directory = si' '  set VTU interval = 5' '  set Probe points = 1, 1' 'end' > si.prm
"$liftoff" -q si.prm >/dev/null 2>si-stderr.txt \
  && "$scripts/liftoff-view" si --size 400,300 --field M_xx >/dev/null 2>>si-stderr.txt
status=$?
si_view=$(awk -F, 'NR > 1 { if ($8 < low) low = $8; b = $4 " " $5 " " $6 " " $7; u = $12 }
  END { print b "|" low "|" u }' low=0 si/pictures/view.csv 2>/dev/null)
[ "$status" -eq 0 ] && [ "$si_view" = "-2.5 2.5 -2.5 2.5|-0.75|kN m/m" ]
check $? "liftoff-view of an SI scene: exit $status; bounds, lowest point and unit of M_xx '$si_view' (want '-2.5 2.5 -2.5 2.5|-0.75|kN m/m')"
# The point load's arrow drawn where the scene puts it: its tip's pixel,
# projected by the picture's camera from the load's point on the warped
# plate, has the arrow's colour (and the plate below it has not).
/usr/bin/python3 "$tests/arrow_pixels.py" si/pictures >arrows.txt
check $? "the point load's arrow tips at their projected pixels: $(grep -c ok arrows.txt) ok, $(grep -c ASTRAY arrows.txt) astray"
[ "$(grep -c ok arrows.txt)" -gt 0 ] || cat arrows.txt
series=$(pvpython "$tests/series_time.py" out 2>/dev/null | tail -1)
same=$(awk -v a="$series" -v b="$pvd_times" 'BEGIN { n = split(a, x, " "); m = split(b, y, " "); ok = (n == m && n == 4); for (i = 1; i <= n; ++i) if ((x[i] - y[i]) ^ 2 > 1e-24) ok = 0; print ok }')
[ "$same" = 1 ]; check $? "the .pvtu series opened without the .pvd has the times $series"
finish
