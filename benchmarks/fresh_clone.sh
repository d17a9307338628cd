#!/usr/bin/env bash
# How long a newcomer waits: the README's two commands, verbatim, in a fresh
# clone of this checkout's HEAD, timed stage by stage.
#
#   benchmarks/fresh_clone.sh [WORK_FOLDER]
#
# The quick start (`bash scripts/quickstart.sh`) is timed as a whole and by
# its stages: the dependencies (scripts/install-dependencies.sh, which is
# only apt's check on a machine that has them), the build of the library
# and the executable, the default scene. The README's test command is read
# from the README (the indented line under "Build and run the tests:") and
# timed as a whole, and its build and ctest separately from the build log
# and ctest's own total. The clone and the builds go to WORK_FOLDER
# (default: a new temporary folder), which is kept. Set CCACHE_DISABLE=1
# (the default here) so that a compiler cache does not hide the compile.
# Prints one line per stage and a table row for the README.
set -euo pipefail
source=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$(mktemp -d "${TMPDIR:-/tmp}/fresh_clone.XXXXXX")}
export CCACHE_DISABLE=${CCACHE_DISABLE:-1}

test_command=$(awk '/^Build and run the tests:/ {found = 1; next}
                    found && /^    [^ ]/ {sub(/^    /, ""); print; exit}' \
                   "$source/README.md")
[ -n "$test_command" ] || { echo "no test command found in README.md" >&2; exit 2; }

git clone -q "$source" "$work/liftoff"
# The paper and its notes sit beside the checkout in the project's layout.
[ -d "$source/../shared" ] && [ ! -e "$work/shared" ] && ln -s "$source/../shared" "$work/shared"
cd "$work/liftoff"

seconds() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.0f", b - a}'; }

t0=$(seconds)
bash scripts/quickstart.sh >"$work/quickstart.log" 2>&1
t1=$(seconds)
# The quick start's stages, measured again on the finished build: apt's
# check and the scene alone (the build is the rest).
bash scripts/install-dependencies.sh >/dev/null 2>&1
t2=$(seconds)
./build/liftoff --overwrite --quiet prm/example-3-square-plate.prm >/dev/null
t3=$(seconds)
quick=$(elapsed "$t0" "$t1")
deps=$(elapsed "$t1" "$t2")
scene=$(elapsed "$t2" "$t3")
echo "quick start: $quick s (dependencies check $deps s, default scene $scene s, build the rest)"

t4=$(seconds)
bash -c "$test_command" >"$work/tests.log" 2>&1 || status=$?
t5=$(seconds)
ctest_seconds=$(sed -n 's/^Total Test time (real) = *\([0-9.]*\) sec/\1/p' "$work/tests.log")
total=$(elapsed "$t4" "$t5")
summary=$(grep -E "tests passed|tests failed" "$work/tests.log" | tail -1)
echo "test command: $total s (ctest ${ctest_seconds:-?} s, configure and build the rest): $summary"
echo "logs: $work/quickstart.log $work/tests.log"
exit "${status:-0}"
