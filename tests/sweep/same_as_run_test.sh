#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# same_as_run_test.sh WRC_CLI: a sweep's run (in the sweep's own process, no bus) ends exactly as
# `wrc run --in-process` on wrc-dynamicsd over the bus with the same options: the same final
# state, counters and run quantities, to the last bit; for the lone wheelset and for a vehicle of
# several bodies (the Cooperrider bogie: its first wheelset's final state, the run's counters).
# ctest runs it on a private bus (clients/lib/netns.sh).
set -euo pipefail
cli=${1:?usage: same_as_run_test.sh WRC_CLI}
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
compare() {  # compare NAME OPTIONS...: the sweep's row against wrc run --in-process's summary
  local name=$1; shift
  "$cli" run "$@" --speed 30 --in-process --summary "$name.json" 2>"$name.err" || { cat "$name.err"; exit 1; }
  paths=final_state.y,final_state.yaw,final_state.roll,final_state.spin_rate,counters.steps,counters.restarts,run_quantities.y_over_q.left.max,run_quantities.track_shift_force.max
  "$cli" sweep --grid speed=30 --extract "$paths" --out "$name-sweep.csv" -- "$@" 2>"$name-sweep.err" ||
    { cat "$name-sweep.err"; exit 1; }
  from_sweep=$(awk -F, 'NR == 2 { for (i = 4; i <= 11; ++i) printf "%s ", $i }' "$name-sweep.csv")
  from_run=$(jq -r '[.final_state.y, .final_state.yaw, .final_state.roll, .final_state.spin_rate, .counters.steps,
    .counters.restarts, .run_quantities.y_over_q.left.max, .run_quantities.track_shift_force.max] | map(tostring) | join(" ")' "$name.json")
  # jq prints doubles with 17 significant digits, the sweep the shortest text that reads back: compare as numbers.
  awk -v a="$from_sweep" -v b="$from_run" 'BEGIN {
    n = split(a, x, " "); m = split(b, y, " ");
    if (n != 8 || m != 8) { print "FAIL: " n " and " m " values"; exit 1 }
    for (i = 1; i <= n; ++i) if (x[i] + 0 != y[i] + 0) { print "FAIL: value " i ": sweep " x[i] ", wrc run " y[i]; exit 1 }
  }' || { echo "$name sweep: $from_sweep"; echo "$name run:   $from_run"; exit 1; }
  echo "PASS: $name: the sweep's run is wrc run --in-process's ($from_sweep)"
}
compare wheelset --model onepoint --t-end 0.3 --friction 0.2 --y0 0.001
compare bogie --model onepoint --t-end 0.3 --friction 0.15 --y0 0.001 --r0 0.425 \
  --vehicle "$root/parameters/vehicles/cooperrider-bogie.json"
# A vehicle's linear critical speed in a sweep is `wrc stability --vehicle`'s (printed to 0.1 mm/s).
bogie=(--model onepoint --friction 0.15 --r0 0.425 --vehicle "$root/parameters/vehicles/cooperrider-bogie.json")
"$cli" sweep --grid speed=30 --extract critical_speed --critical-speeds 100:120:10 --out critical.csv -- \
  "${bogie[@]}" --t-end 0.01 2>critical.err || { cat critical.err; exit 1; }
from_sweep=$(awk -F, 'NR == 2 { printf "%.4f", $4 }' critical.csv)
from_stability=$("$cli" stability "${bogie[@]}" --speeds 100:120:10 --out stability.csv --plot stability.png 2>&1 |
  sed -n 's/^linear critical speed: \([0-9.]*\) m\/s.*/\1/p')
[ -n "$from_sweep" ] && [ "$from_sweep" = "$from_stability" ] ||
  { echo "FAIL: the bogie's critical speed: sweep '$from_sweep', wrc stability '$from_stability'"; exit 1; }
echo "PASS: bogie: the sweep's critical speed is wrc stability's ($from_sweep m/s)"
