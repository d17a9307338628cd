#!/usr/bin/env bash
# Hostile sweep (not in ctest; 1, 2 and 3 ranks took about 60 minutes on the
# 2-core machine beside other work): an adaptive run
# stopped at many steps and resumed must write the same history.csv as one
# run without a stop, for each foundation variant and number of ranks.
#   tests/sweeps/adaptive_resume_sweep.sh LIFTOFF [RANKS...] 
# Prints one line per case and a count; exits 1 if any case differs.
set -u
liftoff=$(realpath "$1"); shift
ranks=("${@:-1}")
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; cd "$work"
dt=5e-4; n=30
variants=(
  "plain|"
  "gap|subsection Foundation\n set Initial gap = 0.001 * (x*x + y*y)\nend"
  "dashpots|subsection Foundation\n set Damping = 2\nend"
  "shear layer|subsection Foundation\n set Shear modulus = 0.5\nend"
  "self weight|subsection Loads\n set Self weight = 0.2\nend"
)
scene() { # scene DIR N_STEPS EXTRA N_RANKS
  printf 'subsection Discretization\n set Symmetry = quarter\n set Cells along x = 8\n set Cells along y = 8\n set Polynomial degree = 2\nend\n'
  printf 'subsection Mesh refinement\n set Adaptive = true\n set Interval = 7\n set Maximum level = 2\n set Initial refinements = 1\nend\n'
  printf 'subsection Loads\n subsection Point load 1\n  set Magnitude = 1\n end\nend\n'
  printf 'subsection Time integration\n set Time step = %s\n set End time = %s\nend\n' $dt "$(awk -v k="$2" -v d=$dt 'BEGIN{printf "%.10g", k*d}')"
  printf 'subsection Output\n set Directory = %s\n set VTU interval = 0\nend\n' "$1"
  [ "$4" -gt 1 ] && printf 'subsection Linear solver\n set Direct solver package = klu\nend\n'
  printf "$3\n"
}
failures=0; cases=0
for np in "${ranks[@]}"; do
  run=("$liftoff"); [ "$np" -gt 1 ] && run=(mpirun --allow-run-as-root --oversubscribe -np "$np" "$liftoff")
  for v in "${variants[@]}"; do
    name=${v%%|*}; extra=${v#*|}
    scene ref $n "$extra" "$np" > ref.prm; rm -rf ref; "${run[@]}" ref.prm > /dev/null 2>&1
    for ((k = 1; k < n; k += (np > 1 ? 3 : 1))); do
      rm -rf out
      scene out $k "$extra" "$np" > a.prm; "${run[@]}" a.prm > /dev/null 2>&1
      scene out $n "$extra" "$np" > b.prm; "${run[@]}" --resume b.prm > b.log 2>&1
      cases=$((cases + 1))
      if ! cmp -s ref/history.csv out/history.csv; then
        failures=$((failures + 1))
        echo "DIFFERS: $np rank(s), $name, resumed after step $k"
      fi
    done
    echo "done: $np rank(s), $name"
  done
done
echo "$cases cases, $failures differ"
[ "$failures" -eq 0 ]
