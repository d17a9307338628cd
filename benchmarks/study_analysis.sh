#!/usr/bin/env bash
# The study tool's re-analysis of a 100-run study against a time budget.
#   benchmarks/study_analysis.sh LIFTOFF FOLDER [BUDGET_SECONDS]
# Makes (once; --reuse keeps the runs) the 100-run study of the beam
# (Example 1: 5 meshes x 2 degrees x 10 time steps, 4e-3 ... 7.8e-6, up to
# 12 800 steps per run; about 9 minutes on two busy cores with --jobs 2),
# then times its re-analysis (--reuse --no-plot: read 100 histories and
# profiles, errors, orders, the spectrum of the time-step error, the
# tables) and fails above the budget (default 30 s of wall time).
set -eu
liftoff=$1
folder=$2
budget=${3:-30}
cd "$(dirname "$0")/.."
study() {
  scripts/liftoff-study prm/example-1-beam.prm --executable "$liftoff" \
    --refine "Discretization/Cells along x=10,20,40,80,160" \
    --degrees 1,2 --time-steps 4e-3,2e-3,1e-3,5e-4,2.5e-4,1.25e-4,6.25e-5,3.125e-5,1.5625e-5,7.8125e-6 \
    --set "Time integration/End time=0.1" \
    --set "Output/Probe points=0, 0; 0.05, 0; 0.15, 0; 0.25, 0" \
    --set "Output/Profile start=0.05, 0" --set "Output/Profile points=46" \
    --set "Output/Profile times=0.05, 0.1" \
    --qoi "w(0.05;0)" --qoi "w(0.15;0)" --qoi "w(0;0)" --qoi contact_fraction@0.03 --qoi profiles \
    --reuse --output "$folder" "$@"
}
study --jobs 2 --no-plot >/dev/null
start=$(date +%s.%N)
study --no-plot >/dev/null
elapsed=$(echo "$(date +%s.%N) - $start" | bc)
echo "re-analysis of the 100-run study: $elapsed s (budget $budget s)"
[ "$(echo "$elapsed <= $budget" | bc)" -eq 1 ]
