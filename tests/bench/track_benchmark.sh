#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# 1 km of curved, irregular track at 30 m/s (issue 19's benchmark): parameters/track-curve-R600-1km.json
# (100 m straight, 90 m transition, 620 m of R = 600 m with 130 mm cant, 90 m transition, 100 m
# straight; cant deficiency 99 mm at 30 m/s) with irregularities from the ERRI low-level spectrum
# (3-70 m, seed 1, written by wrc irregularities), the benchmark wheelset without its lateral load,
# over the bus, at the tolerances of a track run (rtol 1e-4, positions 1e-6 m, rates 1e-4: the
# engineers' quantities within 0.6 % of those at the paper benchmark's 1e-6 / 1e-8 / 1e-6, the
# convergence table in docs/track.md; TOLERANCES="1e-6 1e-8 1e-6" runs those instead). One row per
# model: final y, wall time of the integration (service start-up and the spline fit excluded),
# simulated time / wall time (> 1: faster than real time), steps, restarts, contact queries and
# the largest Y/Q; then the one-point / spline wall-time ratio.
# A benchmark, not a test: run it on a quiet machine, e.g.
#   clients/lib/netns.sh tests/bench/track_benchmark.sh [MODELS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${WRC_BUILD_DIR:-$root/build}"
cli="$build/clients/wrc-cli"
models=("${@:-spline onepoint}")
read -r -a models <<< "${models[*]}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export WRC_CACHE_DIR="${WRC_CACHE_DIR:-$work/cache}"
speed=30
read -r rtol position_tolerance velocity_tolerance <<< "${TOLERANCES:-1e-4 1e-6 1e-4}"
t_end=$(awk -v v="$speed" 'BEGIN { printf "%.6f", 1000 / v }')
"$cli" irregularities --spectrum erri-low --length 1000 --wavelengths 3:70 --seed 1 --out "$work/irr.csv"
echo "1 km: $root/parameters/track-curve-R600-1km.json, ERRI low (3-70 m, seed 1), V = $speed m/s, t_end = $t_end s," \
  "rtol $rtol, position tolerance $position_tolerance m, velocity tolerance $velocity_tolerance m/s"
printf '%-10s %10s %9s %10s %7s %9s %9s %8s\n' model y[mm] wall[s] sim/wall steps restarts queries Y/Q_max
for model in "${models[@]}"; do
  summary="$work/$model.json"
  "$cli" run --model "$model" --t-end "$t_end" --speed "$speed" --lateral-force 0 \
    --track "$root/parameters/track-curve-R600-1km.json" --irregularities "$work/irr.csv" \
    --rtol "$rtol" --position-tolerance "$position_tolerance" --velocity-tolerance "$velocity_tolerance" \
    --output-period 0.01 --summary "$summary" --build-dir "$build" >"$work/log" 2>&1 ||
    { echo "$model failed:"; tail -5 "$work/log"; continue; }
  jq -r --arg m "$model" --argjson t "$t_end" '[$m, .final_state.y * 1e3, .wall_time, $t / .wall_time,
      .counters.steps, .counters.restarts, .counters.contact_queries,
      ([.run_quantities.y_over_q.left.max, .run_quantities.y_over_q.right.max] | max)] | @tsv' "$summary" |
    awk -F'\t' '{ printf "%-10s %10.4f %9.3f %10.1f %7d %9d %9d %8.3f\n", $1, $2, $3, $4, $5, $6, $7, $8 }' |
    tee -a "$work/rows"
done
awk '$1 == "onepoint" { o = $3 } $1 == "spline" { s = $3 }
     END { if (o && s) printf "wall time one-point / spline: %.1f\n", o / s }' "$work/rows"
