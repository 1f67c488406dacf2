#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# same_as_run_test.sh WRC_CLI: a sweep's run (in the sweep's own process, no bus) ends exactly as
# `wrc run --in-process` on wrc-dynamicsd over the bus with the same options: the same final
# state, counters and run quantities, to the last bit. ctest runs it on a private bus
# (clients/lib/netns.sh).
set -euo pipefail
cli=${1:?usage: same_as_run_test.sh WRC_CLI}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
options=(--model onepoint --t-end 0.3 --friction 0.2 --y0 0.001)
"$cli" run "${options[@]}" --speed 30 --in-process --summary run.json 2>run.err || { cat run.err; exit 1; }
paths=final_state.y,final_state.yaw,final_state.roll,final_state.spin_rate,counters.steps,counters.restarts,run_quantities.y_over_q.left.max,run_quantities.track_shift_force.max
"$cli" sweep --grid speed=30 --extract "$paths" -- "${options[@]}" 2>sweep.err || { cat sweep.err; exit 1; }
from_sweep=$(awk -F, 'NR == 2 { for (i = 4; i <= 11; ++i) printf "%s ", $i }' sweep.csv)
from_run=$(jq -r '[.final_state.y, .final_state.yaw, .final_state.roll, .final_state.spin_rate, .counters.steps,
  .counters.restarts, .run_quantities.y_over_q.left.max, .run_quantities.track_shift_force.max] | map(tostring) | join(" ")' run.json)
# jq prints doubles with 17 significant digits, the sweep the shortest text that reads back: compare as numbers.
awk -v a="$from_sweep" -v b="$from_run" 'BEGIN {
  n = split(a, x, " "); m = split(b, y, " ");
  if (n != 8 || m != 8) { print "FAIL: " n " and " m " values"; exit 1 }
  for (i = 1; i <= n; ++i) if (x[i] + 0 != y[i] + 0) { print "FAIL: value " i ": sweep " x[i] ", wrc run " y[i]; exit 1 }
}' || { echo "sweep: $from_sweep"; echo "run:   $from_run"; exit 1; }
echo "PASS: the sweep's run is wrc run --in-process's ($from_sweep)"
