#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Three hosts on one bus, and the benchmark across them equal to the one-host benchmark bit for bit.
#
# Inside the private namespace of clients/lib/netns.sh (run as root: `ip netns add` needs it), three
# network namespaces stand for three machines, each joined to one bridge by a veth pair with an
# address of its own (10.77.0.1-3/24), multicast routed over that link and LCM's ttl 1, as
# docs/deployment.md describes a bus over several machines:
#   h1: wrc-geometryd and the spline contact service (its model from the cache they share)
#   h2: the exact contact services (onepoint, interp, multipoint)
#   h3: wrc-dynamicsd, and `wrc run` for every model
# Each host has its own home and cache directory; they share only the bus key. A fourth host, on a
# bridge of its own, runs the same benchmark with the services `wrc run` starts itself (one host).
# The final states and counters of every model must be equal to every digit, no contact service may
# run on h3, and h1's and h2's services must have answered the queries.
#   usage: clients/lib/netns.sh tests/hosts/three_hosts_test.sh BUILD_DIR [T_END]
# Exit 77 (skipped) when the namespaces cannot be made here.
set -euo pipefail
build=$(cd "${1:?usage: three_hosts_test.sh BUILD_DIR [T_END]}" && pwd)
t_end=${2:-2}
cli="$build/clients/wrc-cli"
models=(onepoint interp multipoint spline)

[ "${WRC_BUS_ISOLATION:-}" = netns ] || { echo "three hosts: not in a private network namespace; skipped"; exit 77; }
command -v ip >/dev/null || { echo "three hosts: no ip (iproute2); skipped"; exit 77; }
tag="wrc$$"
if ! ip netns add "${tag}probe" 2>/dev/null; then
  echo "three hosts: ip netns add is not permitted here; skipped"
  exit 77
fi
ip netns del "${tag}probe"

work=$(mktemp -d)
hosts=(h1 h2 h3 h4)
launchers=()
cleanup() {
  local status=$?
  for pid in "${launchers[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${launchers[@]}"; do wait "$pid" 2>/dev/null || true; done
  for h in "${hosts[@]}"; do ip netns del "$tag$h" 2>/dev/null || true; done
  if [ "$status" -eq 0 ]; then rm -rf "$work"; else echo "three hosts: kept $work for inspection"; fi
}
trap cleanup EXIT

# host NAME BRIDGE ADDRESS: a namespace joined to BRIDGE, multicast routed over its link.
host() {
  local ns="$tag$1"
  ip netns add "$ns"
  ip link add "v$tag$1" type veth peer name eth0 netns "$ns"
  ip link set "v$tag$1" master "$2" up
  ip -n "$ns" link set lo up
  ip -n "$ns" link set eth0 up multicast on
  ip -n "$ns" addr add "$3/24" dev eth0
  ip -n "$ns" route add 224.0.0.0/4 dev eth0
  mkdir -p "$work/$1/home" "$work/$1/cache"
}
for bridge in "b$tag" "c$tag"; do
  ip link add "$bridge" type bridge mcast_snooping 0
  ip link set "$bridge" up
done
host h1 "b$tag" 10.77.0.1
host h2 "b$tag" 10.77.0.2
host h3 "b$tag" 10.77.0.3
host h4 "c$tag" 10.77.1.4

url="udpm://239.255.76.67:7667?ttl=1"
export WRC_BUS_KEY="$work/bus.key"
# on NAME COMMAND...: COMMAND on host NAME, with its own home and cache.
on() {
  local h=$1
  shift
  ip netns exec "$tag$h" env HOME="$work/$h/home" WRC_CACHE_DIR="$work/$h/cache" LCM_DEFAULT_URL="$url" "$@"
}
# launch_on NAME LOG SERVICES...: `wrc launch SERVICES` on host NAME in the background; its pid
# (ip netns exec and env exec it, so the pid is the launcher's) joins launchers.
launch_on() {
  local h=$1 log=$2
  shift 2
  ip netns exec "$tag$h" env HOME="$work/$h/home" WRC_CACHE_DIR="$work/$h/cache" LCM_DEFAULT_URL="$url" \
    "$cli" launch "$@" --build-dir "$build" >"$log" 2>&1 &
  launchers+=($!)
}
# h3's launcher creates the key; the other hosts get a copy of it, as the machines of a bus do.
launch_on h3 "$work/h3.log" dynamics
for _ in $(seq 1 100); do [ -s "$WRC_BUS_KEY" ] && break; sleep 0.1; done
[ -s "$WRC_BUS_KEY" ] || { echo "three hosts: no bus key from h3's launcher"; cat "$work/h3.log"; exit 1; }
launch_on h1 "$work/h1.log" geometry contact-spline
launch_on h2 "$work/h2.log" contact-onepoint contact-interp contact-multipoint

# Every service READY as h3 hears it (the spline service once wrc-geometryd has fitted its model).
ready=0
for _ in $(seq 1 120); do
  on h3 "$cli" status --format csv --duration 0.6 >"$work/status.csv" 2>/dev/null || true
  ready=$(grep -c ',READY,' "$work/status.csv" || true)
  [ "$ready" -ge 6 ] && break
done
if [ "$ready" -lt 6 ]; then
  echo "three hosts: only $ready of 6 services READY as h3 hears them:"
  cat "$work/status.csv" "$work"/h*.log
  exit 1
fi
echo "three hosts: 6 services READY across h1, h2, h3"

# value KEY FILE: the value after "KEY": in a summary (one key per line); the first match.
value() { sed -n "s/^ *\"$1\": \([^,]*\),\{0,1\}$/\1/p" "$2" | head -1 | tr -d '"'; }
keys=(y z roll yaw y_dot z_dot roll_dot yaw_dot spin_rate normal_force_left normal_force_right steps restarts
      contact_queries residual_evals jacobian_evals two_point_entries)
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
  for key in "${keys[@]}"; do
    a=$(value "$key" "$work/three-$model.json")
    b=$(value "$key" "$work/one-$model.json")
    if [ -z "$a" ] || [ "$a" != "$b" ]; then
      echo "three hosts: $model $key = '$a' across three hosts, '$b' on one"
      failed=1
    fi
  done
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
