#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The paper's benchmark (parameters/benchmark.json, or WRC_BENCH_PARAMS=FILE) with every contact
# model, over the bus and with the contact model in the dynamics process (--in-process, for
# comparison only), each from several starts perturbed at rounding level (y0 = 0, 1e-9, 1e-8,
# 1e-7, 1e-6 m; WRC_BENCH_Y0="..." sets them; WRC_BENCH_OPTIONS="..." adds run options to every
# run, e.g. "--two-point-sliding false"): one row per run (final state, wall time of the
# integration, service start-up and the spline fit excluded, and the counters that explain it),
# then per model and contact the median and range over the starts, and the one-point / spline
# ratio of the median wall times. A benchmark, not a test: run it on a quiet machine, e.g.
#   clients/lib/netns.sh tests/bench/dynamics_benchmark.sh [T_END] [MODELS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${WRC_BUILD_DIR:-$root/build}"
cli="$build/clients/wrc-cli"
t_end="${1:-2}"
shift || true
models=("${@:-onepoint interp multipoint spline}")
read -r -a models <<< "${models[*]}"
read -r -a starts <<< "${WRC_BENCH_Y0:-0 1e-9 1e-8 1e-7 1e-6}"
params=()
[ -n "${WRC_BENCH_PARAMS:-}" ] && params=(--params "$WRC_BENCH_PARAMS")
read -r -a options <<< "${WRC_BENCH_OPTIONS:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export WRC_CACHE_DIR="${WRC_CACHE_DIR:-$work/cache}"

# value KEY FILE: the number after "KEY": in a summary written by wrc run (one key per line).
value() { sed -n "s/^ *\"$1\": \([^,]*\),\{0,1\}$/\1/p" "$2" | head -1 | tr -d '"'; }

echo "parameters: ${WRC_BENCH_PARAMS:-parameters/benchmark.json}, t_end = $t_end s, starts y0 = ${starts[*]} m," \
  "options: ${WRC_BENCH_OPTIONS:-none}"
header='%-10s %-10s %7s %10s %10s %10s %9s %7s %9s %7s %8s %7s %9s %8s\n'
printf "$header" model contact y0[m] y[mm] yaw[mrad] z[m] wall[s] steps residuals jacobs restarts 2-point queries rt/real
rows="$work/rows"
: >"$rows"
: >"$work/cost"
for model in "${models[@]}"; do
  for mode in bus in-process; do
    for y0 in "${starts[@]}"; do
      summary="$work/$model-$mode-$y0.json"
      extra=()
      [ "$mode" = in-process ] && extra=(--in-process)
      "$cli" run --model "$model" --t-end "$t_end" --y0 "$y0" --summary "$summary" --build-dir "$build" \
        "${params[@]}" "${options[@]}" "${extra[@]}" >"$work/log" 2>&1 || { echo "$model $mode y0=$y0 failed:"; tail -5 "$work/log"; continue; }
      awk -v m="$model" -v c="$mode" -v y0="$y0" -v y="$(value y "$summary")" -v yaw="$(value yaw "$summary")" \
          -v z="$(value z "$summary")" -v w="$(value wall_time "$summary")" -v t="$t_end" \
          -v s="$(value steps "$summary")" -v r="$(value residual_evals "$summary")" \
          -v j="$(value jacobian_evals "$summary")" -v x="$(value restarts "$summary")" \
          -v p="$(value two_point_entries "$summary")" -v q="$(value contact_queries "$summary")" \
          'BEGIN { printf "%-10s %-10s %7s %10.4f %10.4f %10.6f %9.3f %7d %9d %7d %8d %7d %9d %8.1f\n",
                   m, c, y0, y*1e3, yaw*1e3, z, w, s, r, j, x, p, q, t / w }' | tee -a "$rows"
      if [ "$mode" = bus ]; then
        # where each answered query's bus time went (the run's counters, docs/performance.md)
        line="$model $y0 $(value contact_queries "$summary")"
        for part in round_trip send transfer service_wakeup compute reply client_wakeup; do
          line+=" $(value "bus_${part}_time" "$summary")"
        done
        echo "$line" >>"$work/cost"
      fi
    done
  done
done

# Median and range per model and contact over the starts (y, yaw, wall time, steps, restarts).
echo
printf '%-10s %-10s %-24s %-24s %-22s %-18s %-16s\n' model contact "y [mm] median (range)" "yaw [mrad] median (range)" \
  "wall [s] median (range)" "steps median (range)" "restarts median (range)"
sort -k1,1 -k2,2 -s "$rows" | awk '
  function median(a, n,   i, j, t) { for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j-1] > a[j]; j--) { t = a[j]; a[j] = a[j-1]; a[j-1] = t }
                                     return n % 2 ? a[(n+1)/2] : 0.5 * (a[n/2] + a[n/2+1]) }
  function lo(a, n,   i, v) { v = a[1]; for (i = 2; i <= n; i++) if (a[i] < v) v = a[i]; return v }
  function hi(a, n,   i, v) { v = a[1]; for (i = 2; i <= n; i++) if (a[i] > v) v = a[i]; return v }
  function flush() {
    if (n == 0) return
    printf "%-10s %-10s %8.4f (%.4f..%.4f) %8.4f (%.4f..%.4f) %7.3f (%.3f..%.3f) %6d (%d..%d) %6d (%d..%d)\n",
      key1, key2, median(y, n), lo(y, n), hi(y, n), median(yaw, n), lo(yaw, n), hi(yaw, n),
      median(w, n), lo(w, n), hi(w, n), median(s, n), lo(s, n), hi(s, n), median(x, n), lo(x, n), hi(x, n)
    wall[key1 " " key2] = median(w, n)
    n = 0
  }
  { if ($1 != key1 || $2 != key2) { flush(); key1 = $1; key2 = $2 }
    n++; y[n] = $4; yaw[n] = $5; w[n] = $7; s[n] = $8; x[n] = $11 }
  END { flush()
        for (c in wall) { split(c, k, " "); if (k[1] == "onepoint" && (("spline " k[2]) in wall))
          printf "spline / onepoint median wall time, %s: %.4f (onepoint %.0f times slower)\n", k[2], wall["spline " k[2]] / wall[c], wall[c] / wall["spline " k[2]] } }'

# The bus against in-process, per model, and where a query's bus time goes.
awk '{ key = $1 " " $2; n[key]++; w[key, n[key]] = $7 }
  function median(k,   i, j, t, a, m) { m = n[k]; for (i = 1; i <= m; i++) a[i] = w[k, i]
    for (i = 2; i <= m; i++) for (j = i; j > 1 && a[j-1] > a[j]; j--) { t = a[j]; a[j] = a[j-1]; a[j-1] = t }
    return m % 2 ? a[(m+1)/2] : 0.5 * (a[m/2] + a[m/2+1]) }
  END { for (k in n) { split(k, p, " "); if (p[2] == "bus" && ((p[1] " in-process") in n))
          printf "%s: bus / in-process median wall time %.2f\n", p[1], median(k) / median(p[1] " in-process") } }' "$rows"
echo
echo "per answered query over the bus [us]: round trip = send + transfer + service wake-up + compute + reply + client wake-up"
printf '%-10s %7s %8s %10s %8s %9s %9s %8s %8s %9s\n' model y0 queries round-trip send transfer svc-wake compute reply cli-wake
awk '{ q = $3 > 0 ? $3 : 1; printf "%-10s %7s %8d %10.1f %8.1f %9.1f %9.1f %8.1f %8.1f %9.1f\n", $1, $2, $3,
       $4/q*1e6, $5/q*1e6, $6/q*1e6, $7/q*1e6, $8/q*1e6, $9/q*1e6, $10/q*1e6 }' "$work/cost"
