#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Load shared between hosts (the hosts: tests/hosts/hosts.sh). h1 runs wrc-geometryd and a spline
# service `a`, h2 a spline service `b` (its model in pieces from h1: no shared folder), h3 a sweep of
# 8 runs on the bus (`wrc sweep --bus --jobs 4`, each run on a wrc-dynamicsd of its own). Then:
# - every run finished, and its queries went to both instances (the sweep's `instances` column,
#   from the run summaries), in counts that differ by at most two and add up to its queries;
# - h3's `wrc status` counts queries handled by both a and b;
# - every run ends where the same sweep in-process ends, every digit of the final state.
#   usage: clients/lib/netns.sh tests/hosts/load_shared_test.sh BUILD_DIR [T_END]
set -euo pipefail
build=$(cd "${1:?usage: load_shared_test.sh BUILD_DIR [T_END]}" && pwd)
t_end=${2:-0.5}
source "$(dirname "${BASH_SOURCE[0]}")/hosts.sh"
hosts_init "load shared"

bridge lan
host h1 lan 10.77.0.1
host h2 lan 10.77.0.2
host h3 lan 10.77.0.3
printf 'contact-spline-b wrc-contactd --model spline --instance b\n' >"$work/b.txt"
launch_on h1 "$work/h1.log" geometry contact-spline
wait_for_key "$work/h1.log"
launch_on h2 "$work/h2.log" --profile "$work/b.txt" contact-spline-b
wait_ready h3 3

grid=(--grid "y0=0,1e-9,1e-8,1e-7,1e-6,2e-6,5e-6,1e-5")
run_options=(--model spline --t-end "$t_end")
on h3 "$cli" sweep --bus --jobs 4 "${grid[@]}" --extract final,counters,instances --out "$work/bus.csv" \
  -- "${run_options[@]}" --build-dir "$build" >"$work/bus.log" 2>&1 ||
  { echo "load shared: the sweep on the bus failed:"; tail -20 "$work/bus.log"; cat "$work"/bus.csv.work/logs/* 2>/dev/null | tail -40; exit 1; }
on h3 "$cli" sweep --jobs 4 "${grid[@]}" --extract final --out "$work/local.csv" -- "${run_options[@]}" \
  >"$work/local.log" 2>&1 || { echo "load shared: the sweep in-process failed:"; tail -20 "$work/local.log"; exit 1; }

# column NAME FILE: the values of the column whose header starts with NAME, one per line (point order).
column() {
  awk -F, -v name="$1" 'NR == 1 { for (i = 1; i <= NF; i++) if (index($i, name) == 1) c = i; next } c { print $c }' "$2"
}
rows=$(column status "$work/bus.csv" | grep -c '^finished$' || true)
[ "$rows" -eq 8 ] || { echo "load shared: $rows of 8 runs on the bus finished:"; cat "$work/bus.csv"; exit 1; }
paste -d' ' <(column query_instances "$work/bus.csv") <(column counters.contact_queries "$work/bus.csv") |
  awk '{ a = b = 0
         for (i = 1; i < NF; i++) { split($i, p, "="); if (p[1] == "spline/a") a = p[2]; else if (p[1] == "spline/b") b = p[2]; else bad = 1 }
         d = a - b; if (d < 0) d = -d
         if (bad || a == 0 || b == 0 || d > 2 || a + b != $NF) { print "load shared: run " NR ": " $0 " (spline/a=A spline/b=B queries)"; fail = 1 } }
       END { exit fail }' || exit 1
for key in y z roll yaw y_dot yaw_dot; do
  if ! diff <(column "final_state.$key" "$work/bus.csv") <(column "final_state.$key" "$work/local.csv") >/dev/null; then
    echo "load shared: final_state.$key differs between the bus and in-process:"
    paste -d' ' <(column "final_state.$key" "$work/bus.csv") <(column "final_state.$key" "$work/local.csv")
    exit 1
  fi
done

# h3's view of the services: both instances handled queries.
on h3 "$cli" status --format csv --duration 1.2 >"$work/status.csv" 2>/dev/null || true
handled() { awk -F, -v i="$1" '$1 == "spline" && $2 == i { print $8 }' "$work/status.csv" | head -1; }
a=$(handled a)
b=$(handled b)
if [ "${a:-0}" -le 0 ] || [ "${b:-0}" -le 0 ]; then
  echo "load shared: wrc status counts a ${a:-?} and b ${b:-?} queries handled"
  cat "$work/status.csv"
  exit 1
fi
echo "load shared: 8 runs on the bus, each run's queries over a and b: $(column query_instances "$work/bus.csv" | head -1)" \
  "(first run); wrc status: a handled $a, b $b; final states as in-process; PASS"
