#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The Manchester coach (parameters/vehicles/manchester-coach.json: a car body on two bogies, four
# wheelsets) on parameters/track-curve-R600-1km.json with ERRI low-level irregularities (3-70 m,
# seed 1, 1050 m: no wheelset leaves them before the track's end) at 30 m/s, in-process and over
# the bus in one run, at the tolerances of a track run (rtol 1e-4, positions 1e-6 m, rates 1e-4;
# TOLERANCES="1e-6 1e-8 1e-6" runs the paper benchmark's instead). One row per model and way:
# wall time of the integration (service start-up and the spline fit excluded), simulated time /
# wall time (> 1: faster than real time), steps, residual evaluations, Newton matrices, contact
# queries (batches: round trips over the bus) and configurations, and the front bogie's leading
# wheelset's 2 m sliding mean of Y/Q. T_END (default 33.7 s: the last wheelset past the track's
# end) sets the run's length. The spline model is fitted over flange contact too (FIT, default
# "--box -0.012:0.012,0.004,0.005 --knots 20x4x2": the stiff bogies' leading wheelsets run 6 to 11
# mm out in the curve, beyond the default box's tread; docs/vehicle.md), in-process by the
# dynamics and over the bus by the spline service the run starts (fit time excluded from both;
# FIT= fits the default box).
# A benchmark, not a test: run it on a quiet machine, e.g.
#   clients/lib/netns.sh tests/bench/vehicle_benchmark.sh [MODELS...]   (default: spline)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${WRC_BUILD_DIR:-$root/build}"
cli="$build/clients/wrc-cli"
models=("${@:-spline}")
read -r -a models <<< "${models[*]}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export WRC_CACHE_DIR="${WRC_CACHE_DIR:-$work/cache}"
speed=30
t_end="${T_END:-33.7}"
read -r -a fit <<< "${FIT---box -0.012:0.012,0.004,0.005 --knots 20x4x2}"
read -r rtol position_tolerance velocity_tolerance <<< "${TOLERANCES:-1e-4 1e-6 1e-4}"
"$cli" irregularities --spectrum erri-low --length 1050 --wavelengths 3:70 --seed 1 --out "$work/irr.csv"
echo "coach: $root/parameters/vehicles/manchester-coach.json on $root/parameters/track-curve-R600-1km.json," \
  "ERRI low (3-70 m, seed 1), V = $speed m/s, t_end = $t_end s, rtol $rtol, position tolerance" \
  "$position_tolerance m, velocity tolerance $velocity_tolerance m/s; spline fit: ${fit[*]}"
printf '%-10s %-10s %9s %9s %7s %9s %8s %9s %9s %8s\n' model way wall[s] sim/wall steps residuals matrices \
  queries configs Y/Q_2m
for model in "${models[@]}"; do
  for way in in-process bus; do
    summary="$work/$model-$way.json"
    flag=()
    [ "$way" = in-process ] && flag=(--in-process)
    [ "$model" = spline ] && flag+=("${fit[@]}")
    "$cli" run --model "$model" "${flag[@]}" --vehicle "$root/parameters/vehicles/manchester-coach.json" \
      --t-end "$t_end" --speed "$speed" --track "$root/parameters/track-curve-R600-1km.json" \
      --irregularities "$work/irr.csv" --rtol "$rtol" --position-tolerance "$position_tolerance" \
      --velocity-tolerance "$velocity_tolerance" --output-period 0.01 --summary "$summary" \
      --dynamics-instance "bench-$model-$way" --build-dir "$build" >"$work/log" 2>&1 ||
      { echo "$model $way failed:"; tail -3 "$work/log"; continue; }
    jq -r --arg m "$model" --arg w "$way" --argjson t "$t_end" '[$m, $w, .wall_time, $t / .wall_time,
        .counters.steps, .counters.residual_evals + .counters.jacobian_residual_evals, .counters.jacobian_evals,
        .counters.contact_queries, .counters.contact_configurations,
        (.vehicle.wheelsets[0].run_quantities.y_over_q_2m | [.left.max, .right.max] | max)] | @tsv' "$summary" |
      awk -F'\t' '{ printf "%-10s %-10s %9.3f %9.1f %7d %9d %8d %9d %9d %8.3f\n", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10 }' |
      tee -a "$work/rows"
  done
done
awk '$2 == "in-process" { i[$1] = $3 } $2 == "bus" { b[$1] = $3 }
     END { for (m in i) if (m in b) printf "%s: wall time over the bus / in-process: %.2f\n", m, b[m] / i[m] }' "$work/rows"
