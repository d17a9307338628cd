#!/usr/bin/env bash
# liftoff --help and -h print the usage to stdout and exit 0; --version
# prints the version of CMakeLists.txt and the git commit of the source tree
# (asked of git here, independently of the build), or "unknown" for a
# source tree outside git (cmake/version.cmake run on a copy, as for a
# tarball); a wrong option still ends in the usage on stderr and exit 2.
# The options that only print start no MPI, and answer once under mpirun.
#   command_line.sh LIFTOFF SOURCE_DIR
set -u
liftoff=$1
source_dir=$2
source "$(dirname "$0")/../common/output_checks.sh"
enter_work_directory

for option in --help -h; do
  "$liftoff" "$option" >stdout.txt 2>stderr.txt
  status=$?
  [ "$status" -eq 0 ] && grep -q '^usage: liftoff SCENE.prm' stdout.txt && grep -q -- '--version' stdout.txt && [ ! -s stderr.txt ]
  check $? "$option: exit $status, usage on stdout, nothing on stderr"
done

version=$(sed -n 's/^project(liftoff VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")
"$liftoff" --version >stdout.txt 2>stderr.txt
status=$?
printed=$(cat stdout.txt)
if commit=$(git -C "$source_dir" rev-parse --short=12 HEAD 2>/dev/null) \
   && [ "$(cd "$(git -C "$source_dir" rev-parse --show-toplevel)" && pwd -P)" = "$(cd "$source_dir" && pwd -P)" ]; then
  expected="liftoff $version (git $commit"
else
  expected="liftoff $version (git unknown)"
fi
[ "$status" -eq 0 ] && [ -n "$version" ] && [[ "$printed" == "$expected"* ]] && [ ! -s stderr.txt ]
check $? "--version: exit $status, '$printed' starts with '$expected'"

# The options that only print start no MPI (most of their time): with a
# transport that does not exist, which MPI_Init refuses, they still answer.
for option in --help --version --parameters; do
  OMPI_MCA_pml=no_such_transport "$liftoff" "$option" >stdout.txt 2>stderr.txt
  status=$?
  [ "$status" -eq 0 ] && [ -s stdout.txt ] && [ ! -s stderr.txt ]
  check $? "$option starts no MPI: exit $status with OMPI_MCA_pml=no_such_transport"
done
# Under mpirun every rank gets the option; one answers.
mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" --version >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 0 ] && [ "$(wc -l <stdout.txt)" -eq 1 ]
check $? "mpirun -np 2 liftoff --version: exit $status, $(wc -l <stdout.txt) line(s)"

mkdir tarball
cmake -DSOURCE_DIR="$PWD/tarball" -DOUTPUT="$PWD/version.h" -DVERSION=9.9.9 \
      -P "$source_dir/cmake/version.cmake"
grep -q '#define LIFTOFF_GIT_COMMIT "unknown"' version.h && grep -q '#define LIFTOFF_VERSION "9.9.9"' version.h
check $? "a source tree outside git: the commit is 'unknown'"

"$liftoff" --no-such-option >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 2 ] && grep -q '^usage: liftoff' stderr.txt && [ ! -s stdout.txt ]
check $? "--no-such-option: exit $status, usage on stderr"
grep -q '^liftoff: unknown option --no-such-option' stderr.txt
check $? "--no-such-option: the reason first"

# Two starts that exclude each other: the reason, not only the usage.
"$liftoff" --resume --overwrite scene.prm >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 2 ] && grep -q '^liftoff: --resume continues the results .* --overwrite removes them: give one of them, not both' stderr.txt && grep -q '^usage: liftoff' stderr.txt
check $? "--resume --overwrite: exit $status, the reason and the usage on stderr"
"$liftoff" a.prm b.prm >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 2 ] && grep -q '^liftoff: one scene file at a time, not 2' stderr.txt
check $? "two scene files: exit $status, the reason on stderr"

# --quiet: one line on the terminal, also for an SI scene (its groups) and
# a static analysis (its iterations), where it printed 3 and 4.
cat > quiet.prm <<'EOF2'
subsection Units
  set System           = SI
  set Length           = 4
  set Width            = 4
  set Thickness        = 0.25
  set Young's modulus  = 30e9
  set Density          = 2400
  set Subgrade modulus = 50e6
end
subsection Analysis
  set Type = static
end
subsection Discretization
  set Cells along x = 4
  set Cells along y = 4
end
subsection Output
  set Directory = quiet
end
EOF2
"$liftoff" -q quiet.prm >stdout.txt 2>stderr.txt
status=$?
[ "$status" -eq 0 ] && [ "$(wc -l < stdout.txt)" -eq 1 ] && grep -q '^status: completed; summary in quiet/summary.txt$' stdout.txt && [ ! -s stderr.txt ]
check $? "-q: exit $status, one status line ($(wc -l < stdout.txt) lines)"
finish
