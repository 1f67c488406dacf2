#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Three hosts on one bus, and the benchmark across them equal to the one-host benchmark bit for bit
# (the hosts: tests/hosts/hosts.sh):
#   h1: wrc-geometryd and the spline contact service (its model from the cache they share)
#   h2: the exact contact services (onepoint, interp, multipoint)
#   h3: wrc-dynamicsd, and `wrc run` for every model
# A fourth host, on a bridge of its own, runs the same benchmark with the services `wrc run` starts
# itself (one host). The final states and counters of every model must be equal to every digit, no
# contact service may run on h3, and h1's and h2's services must have answered the queries.
#   usage: clients/lib/netns.sh tests/hosts/three_hosts_test.sh BUILD_DIR [T_END]
set -euo pipefail
build=$(cd "${1:?usage: three_hosts_test.sh BUILD_DIR [T_END]}" && pwd)
t_end=${2:-2}
source "$(dirname "${BASH_SOURCE[0]}")/hosts.sh"
hosts_init "three hosts"
models=(onepoint interp multipoint spline)

bridge lan
bridge alone
host h1 lan 10.77.0.1
host h2 lan 10.77.0.2
host h3 lan 10.77.0.3
host h4 alone 10.77.1.4
launch_on h3 "$work/h3.log" dynamics
wait_for_key "$work/h3.log"
launch_on h1 "$work/h1.log" geometry contact-spline
launch_on h2 "$work/h2.log" contact-onepoint contact-interp contact-multipoint
wait_ready h3 6
echo "three hosts: 6 services READY across h1, h2, h3"

failed=0
for model in "${models[@]}"; do
  on h3 "$cli" run --model "$model" --t-end "$t_end" --summary "$work/three-$model.json" --build-dir "$build" \
    >"$work/three-$model.log" 2>&1 || { echo "three hosts: $model failed:"; tail -5 "$work/three-$model.log"; exit 1; }
  if grep -q "starting" "$work/three-$model.log"; then
    echo "three hosts: wrc run on h3 started a service of its own for $model:"
    cat "$work/three-$model.log"
    exit 1
  fi
  on h4 "$cli" run --model "$model" --t-end "$t_end" --summary "$work/one-$model.json" --build-dir "$build" \
    >"$work/one-$model.log" 2>&1 || { echo "one host: $model failed:"; tail -5 "$work/one-$model.log"; exit 1; }
  same_state "$work/three-$model.json" "$work/one-$model.json" "$model across three hosts against one" || failed=1
  printf 'three hosts: %-10s y = %s m, %s steps, %s contact queries: the same on one host\n' "$model" \
    "$(value y "$work/three-$model.json")" "$(value steps "$work/three-$model.json")" \
    "$(value contact_queries "$work/three-$model.json")"
done
[ "$failed" -eq 0 ] || exit 1

# The queries were answered on h1 and h2: their contact services count what they handled.
on h3 "$cli" status --format csv --duration 0.6 >"$work/status.csv" 2>/dev/null || true
for model in "${models[@]}"; do
  handled=$(awk -F, -v m="$model" '$1 == m && $4 == "READY" { print $8 }' "$work/status.csv" | head -1)
  if [ -z "$handled" ] || [ "$handled" -le 0 ]; then
    echo "three hosts: the $model service reports '$handled' queries handled"
    cat "$work/status.csv"
    exit 1
  fi
done
echo "three hosts: every model's service on h1 or h2 answered (wrc status: handled > 0); PASS"
