#!/usr/bin/env bash
# The paper's benchmark (parameters/benchmark.json) with every contact model, over the bus and with
# the contact model in the dynamics process (--in-process, for comparison only): final state, wall
# time of the integration (service start-up and the spline fit excluded) and the counters that
# explain it, one table row per run. A benchmark, not a test: run it on a quiet machine, e.g.
#   clients/lib/netns.sh tests/bench/dynamics_benchmark.sh [T_END] [MODELS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${WRC_BUILD_DIR:-$root/build}"
cli="$build/clients/wrc-cli"
t_end="${1:-2}"
shift || true
models=("${@:-onepoint interp multipoint spline}")
read -r -a models <<< "${models[*]}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export WRC_CACHE_DIR="${WRC_CACHE_DIR:-$work/cache}"

# value KEY FILE: the number after "KEY": in a summary written by wrc run (one key per line).
value() { sed -n "s/^ *\"$1\": \([^,]*\),\{0,1\}$/\1/p" "$2" | head -1 | tr -d '"'; }

printf '%-10s %-10s %10s %10s %10s %9s %7s %9s %7s %8s %9s %8s\n' model contact y[mm] yaw[mrad] z[m] wall[s] steps residuals jacobs restarts queries rt/real
for model in "${models[@]}"; do
  for mode in bus in-process; do
    summary="$work/$model-$mode.json"
    extra=()
    [ "$mode" = in-process ] && extra=(--in-process)
    "$cli" run --model "$model" --t-end "$t_end" --summary "$summary" --build-dir "$build" "${extra[@]}" \
      >"$work/log" 2>&1 || { echo "$model $mode failed:"; tail -5 "$work/log"; continue; }
    y=$(value y "$summary"); yaw=$(value yaw "$summary"); z=$(value z "$summary"); wall=$(value wall_time "$summary")
    awk -v m="$model" -v c="$mode" -v y="$y" -v yaw="$yaw" -v z="$z" -v w="$wall" -v t="$t_end" \
        -v s="$(value steps "$summary")" -v r="$(value residual_evals "$summary")" \
        -v j="$(value jacobian_evals "$summary")" -v x="$(value restarts "$summary")" \
        -v q="$(value contact_queries "$summary")" \
        'BEGIN { printf "%-10s %-10s %10.4f %10.4f %10.6f %9.3f %7d %9d %7d %8d %9d %8.1f\n", m, c, y*1e3, yaw*1e3, z, w, s, r, j, x, q, t / w }'
  done
done
