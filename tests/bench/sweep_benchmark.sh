#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# sweep_benchmark.sh [WRC_CLI]: a benchmark, not a test. The same 16-run 2-parameter grid (speed x
# friction, benchmark wheelset, one-point contact) swept with --jobs 1 and with --jobs 2, and the
# ratio of their wall times (at most 0.6 is what issue 20 asks of two cores). The two CSVs must be
# the same but for wall_time [s] (wrc sweep --compare). Run it on an otherwise idle machine.
#   WRC_SWEEP_T_END   simulated time per run [s] (default 0.5)
#   WRC_SWEEP_REPEAT  pairs of sweeps, alternating (default 3): the ratio of the fastest of each
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cli=${1:-${WRC_BUILD_DIR:-$root/build}/clients/wrc-cli}
t_end=${WRC_SWEEP_T_END:-0.5}
repeat=${WRC_SWEEP_REPEAT:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
grid=(--grid speed=10:40:10 --grid friction=0.15,0.2,0.3,0.4 -- --model onepoint --t-end "$t_end")
now_ms() { echo $(($(date +%s%N) / 1000000)); }
run() {  # run JOBS OUT: prints the wall time [ms]
  local start
  start=$(now_ms)
  "$cli" sweep --jobs "$1" --out "$dir/$2" "${grid[@]}" 2>"$dir/$2.err" || { cat "$dir/$2.err" >&2; exit 1; }
  echo $(($(now_ms) - start))
}
echo "wrc sweep: 16 runs (speed 10:40:10 m/s x friction 0.15,0.2,0.3,0.4), onepoint, t_end = $t_end s, $(nproc) cores"
# Another busy process halves what two jobs can gain (the scheduler shares the cores between
# sessions whatever their nice value): the load before, to read the ratio by.
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
one=
two=
for i in $(seq "$repeat"); do
  rm -rf "$dir"/*.csv "$dir"/*.work
  a=$(run 1 one.csv)
  b=$(run 2 two.csv)
  "$cli" sweep --compare "$dir/one.csv" "$dir/two.csv" >/dev/null || { "$cli" sweep --compare "$dir/one.csv" "$dir/two.csv"; exit 1; }
  sum=$(awk -F, 'NR > 1 { s += $NF } END { printf "%.1f", s }' "$dir/one.csv")
  printf "pair %d: jobs 1 %d.%03d s (its runs' own wall times add up to %s s), jobs 2 %d.%03d s, ratio %s\n" "$i" \
    $((a / 1000)) $((a % 1000)) "$sum" $((b / 1000)) $((b % 1000)) "$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.3f", b / a }')"
  [ -n "$one" ] && [ "$one" -le "$a" ] || one=$a
  [ -n "$two" ] && [ "$two" -le "$b" ] || two=$b
done
echo "the two CSVs of every pair are the same but for wall_time [s]"
printf "jobs 1: %d.%03d s wall (fastest of %d)\n" $((one / 1000)) $((one % 1000)) "$repeat"
printf "jobs 2: %d.%03d s wall (fastest of %d)\n" $((two / 1000)) $((two % 1000)) "$repeat"
awk -v a="$one" -v b="$two" 'BEGIN { printf "ratio jobs 2 / jobs 1: %.3f\n", b / a }'
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
