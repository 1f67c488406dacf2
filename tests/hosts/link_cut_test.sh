#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A host lost and found (the hosts: tests/hosts/hosts.sh). Two instances of the one-point contact
# service on two hosts, `a` on h2 and `b` on h1, wrc-dynamicsd on h3. While h3 runs the paper's
# benchmark with the one-point model, h2's link is cut (nft drops everything on its eth0) and, once
# b has taken the queries over, restored. Then:
# - the run ends as the same run on one host does (a fourth host), every digit: nothing is lost;
# - a answered before the cut, b during it;
# - h2's services rejoin: h3 hears a and b READY, none DUPLICATE, and a second run's queries are
#   spread over both again (each handles some).
#   usage: clients/lib/netns.sh tests/hosts/link_cut_test.sh BUILD_DIR [T_END]
set -euo pipefail
build=$(cd "${1:?usage: link_cut_test.sh BUILD_DIR [T_END]}" && pwd)
t_end=${2:-2}
source "$(dirname "${BASH_SOURCE[0]}")/hosts.sh"
hosts_init "link cut"
command -v nft >/dev/null || { echo "link cut: no nft (nftables); skipped"; exit 77; }

bridge lan
bridge alone
host h1 lan 10.77.0.1
host h2 lan 10.77.0.2
host h3 lan 10.77.0.3
host h4 alone 10.77.1.4
printf 'contact-onepoint-b wrc-contactd --model onepoint --instance b\n' >"$work/b.txt"
launch_on h3 "$work/h3.log" dynamics
wait_for_key "$work/h3.log"
launch_on h2 "$work/h2.log" contact-onepoint
launch_on h1 "$work/h1.log" --profile "$work/b.txt" contact-onepoint-b
wait_ready h3 3

on h4 "$cli" run --model onepoint --t-end "$t_end" --summary "$work/one.json" --build-dir "$build" \
  >"$work/one.log" 2>&1 || { echo "link cut: the one-host run failed:"; tail -5 "$work/one.log"; exit 1; }

# status_of INSTANCE COLUMN: a column of the one-point INSTANCE's line in the last status.
status_of() { awk -F, -v i="$1" -v c="$2" '$1 == "onepoint" && $2 == i { print $c }' "$work/status.csv" | head -1; }
status() { on h3 "$cli" status --format csv --duration 0.5 >"$work/status.csv" 2>/dev/null || true; }
# until_status CONDITION LIMIT: polls h3's status until CONDITION (a shell command) holds, LIMIT polls.
until_status() {
  for _ in $(seq 1 "$2"); do
    status
    if eval "$1"; then return 0; fi
  done
  return 1
}

on h3 "$cli" run --model onepoint --t-end "$t_end" --summary "$work/cut.json" --build-dir "$build" \
  >"$work/cut.log" 2>&1 &
run=$!
# Mid-run: the dynamics past t = 0.1 s (its activity on h3's status) and a's heartbeat counting the
# queries it answered (a heartbeat reports the counts of its period: the first may come after t = 0.1 s).
running() {
  awk -F, '$1 == "dynamicsd" && match($0, /, t = [0-9.e+-]+ of /) { if (substr($0, RSTART + 6) + 0 > 0.1) ok = 1 }
           END { exit !ok }' "$work/status.csv" || return 1
  local answered
  answered=$(status_of a 8)
  [ "${answered:-0}" -gt 0 ]
}
until_status running 60 || { echo "link cut: the run did not get past t = 0.1 s with a answering"; cat "$work/status.csv"; exit 1; }
a_before=$(status_of a 8)
b_before=$(status_of b 8)
[ "${a_before:-0}" -gt 0 ] || { echo "link cut: instance a answered nothing before the cut"; cat "$work/status.csv"; exit 1; }

# The cut: everything in and out of h2's eth0 dropped.
on h2 nft add table inet cut
on h2 nft add chain inet cut in '{ type filter hook input priority 0; policy accept; }'
on h2 nft add chain inet cut out '{ type filter hook output priority 0; policy accept; }'
on h2 nft add rule inet cut in iifname eth0 drop
on h2 nft add rule inet cut out oifname eth0 drop
cut_at=$(date +%s.%N)
took_over() { [ "$(status_of b 8)" -gt "${b_before:-0}" ]; }
if ! until_status took_over 60; then
  echo "link cut: instance b did not take the queries over"
  cat "$work/status.csv"
  exit 1
fi
on h2 nft delete table inet cut
echo "link cut: h2 cut off for $(awk -v a="$cut_at" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s;" \
  "b answered $(( $(status_of b 8) - ${b_before:-0} )) queries meanwhile"

wait "$run" || { echo "link cut: the run failed:"; tail -5 "$work/cut.log"; exit 1; }
same_state "$work/cut.json" "$work/one.json" "the run with the link cut against one host" || exit 1
echo "link cut: the run ended as on one host: y = $(value y "$work/cut.json") m, $(value steps "$work/cut.json") steps"

# Rejoined: both READY as h3 hears them, none DUPLICATE; then both answer the next run's queries.
both_ready() { [ "$(status_of a 4)" = READY ] && [ "$(status_of b 4)" = READY ]; }
until_status both_ready 60 || { echo "link cut: a and b are not both READY after the cut"; cat "$work/status.csv"; exit 1; }
if grep -q DUPLICATE "$work/status.csv"; then echo "link cut: a DUPLICATE after the cut"; cat "$work/status.csv"; exit 1; fi
a_rejoined=$(status_of a 8)
b_rejoined=$(status_of b 8)
on h3 "$cli" run --model onepoint --t-end 0.2 --summary "$work/after.json" --build-dir "$build" \
  >"$work/after.log" 2>&1 || { echo "link cut: the run after the cut failed:"; tail -5 "$work/after.log"; exit 1; }
# The counts come with each instance's next heartbeats, and a 0.5 s status may miss one instance's:
# polled until both are read and have grown, or 20 polls.
answered_after() {
  a_after=$(status_of a 8)
  b_after=$(status_of b 8)
  [ -n "$a_after" ] && [ -n "$b_after" ] && [ "$a_after" -gt "$a_rejoined" ] && [ "$b_after" -gt "$b_rejoined" ]
}
if ! until_status answered_after 20; then
  echo "link cut: after the rejoin a answered $((a_after - a_rejoined)) and b $((b_after - b_rejoined)) queries" \
    "of one run (both should)"
  cat "$work/status.csv"
  exit 1
fi
echo "link cut: after the rejoin a answered $((a_after - a_rejoined)) and b $((b_after - b_rejoined)) queries of a run; PASS"
