#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Test hosts: network namespaces that stand for machines of one LAN, sourced by the tests of
# tests/hosts/. Inside the private namespace of clients/lib/netns.sh (as root: `ip netns add` needs
# it), each host is joined to a bridge by a veth pair with an address of its own, multicast routed
# over that link, LCM's ttl 1 (docs/deployment.md), a home and a cache directory of its own; the
# hosts share the bus key file. Before sourcing: build (the build tree). After: hosts_init exits 77
# (skipped) where the namespaces cannot be made; cleanup runs at exit.
cli="$build/clients/wrc-cli"
tag="wrc$$"
url="udpm://239.255.76.67:7667?ttl=1"
launchers=()
made_hosts=()
made_bridges=()

# hosts_init NAME: checks that namespaces can be made here (else exit 77), makes the work folder.
hosts_init() {
  test_name=$1
  [ "${WRC_BUS_ISOLATION:-}" = netns ] || { echo "$test_name: not in a private network namespace; skipped"; exit 77; }
  command -v ip >/dev/null || { echo "$test_name: no ip (iproute2); skipped"; exit 77; }
  if ! ip netns add "${tag}probe" 2>/dev/null; then
    echo "$test_name: ip netns add is not permitted here; skipped"
    exit 77
  fi
  ip netns del "${tag}probe"
  work=$(mktemp -d)
  export WRC_BUS_KEY="$work/bus.key"
  trap hosts_cleanup EXIT
}

hosts_cleanup() {
  local status=$?
  for pid in "${launchers[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${launchers[@]}"; do wait "$pid" 2>/dev/null || true; done
  for h in "${made_hosts[@]}"; do ip netns del "$tag$h" 2>/dev/null || true; done
  for b in "${made_bridges[@]}"; do ip link del "$b" 2>/dev/null || true; done
  if [ "$status" -eq 0 ]; then rm -rf "$work"; else echo "$test_name: kept $work for inspection"; fi
}

# bridge NAME: a bridge that floods multicast (no snooping: no querier runs here).
bridge() {
  ip link add "$tag$1" type bridge mcast_snooping 0
  ip link set "$tag$1" up
  made_bridges+=("$tag$1")
}

# host NAME BRIDGE ADDRESS: a namespace whose eth0 is joined to BRIDGE with ADDRESS/24.
host() {
  local ns="$tag$1"
  ip netns add "$ns"
  made_hosts+=("$1")
  ip link add "v$tag$1" type veth peer name eth0 netns "$ns"
  ip link set "v$tag$1" master "$tag$2" up
  ip -n "$ns" link set lo up
  ip -n "$ns" link set eth0 up multicast on
  ip -n "$ns" addr add "$3/24" dev eth0
  ip -n "$ns" route add 224.0.0.0/4 dev eth0
  mkdir -p "$work/$1/home" "$work/$1/cache"
}

# host_command NAME: sets host_cmd to the command prefix that runs a command on host NAME, with its
# own home and cache; the other hosts' folders are hidden from it (an empty tmpfs over each, in a
# mount namespace of its own), as another machine's disk is: a file path from another host does
# not resolve there. Each part execs the next, so a command started with it keeps its pid.
host_command() {
  local h=$1 hidden=() other
  for other in "${made_hosts[@]}"; do [ "$other" = "$h" ] || hidden+=("$work/$other"); done
  host_cmd=(ip netns exec "$tag$h" unshare -m --propagation private sh -c
    'n=$1; shift; while [ "$n" -gt 0 ]; do mount -t tmpfs tmpfs "$1"; shift; n=$((n - 1)); done; exec "$@"'
    sh "${#hidden[@]}" "${hidden[@]}" env HOME="$work/$h/home" WRC_CACHE_DIR="$work/$h/cache" LCM_DEFAULT_URL="$url")
}

# on NAME COMMAND...: COMMAND on host NAME (host_command).
on() {
  local host_cmd
  host_command "$1"
  shift
  "${host_cmd[@]}" "$@"
}

# launch_on NAME LOG [wrc launch arguments...]: `wrc launch` on host NAME in the background; its
# pid, the launcher's, joins launchers.
launch_on() {
  local host_cmd log=$2
  host_command "$1"
  shift 2
  "${host_cmd[@]}" "$cli" launch "$@" --build-dir "$build" >"$log" 2>&1 &
  launchers+=($!)
}

# wait_for_key LOG: until the first launcher has created the bus key (which the other hosts then
# share, as the machines of a bus get a copy of it).
wait_for_key() {
  for _ in $(seq 1 100); do [ -s "$WRC_BUS_KEY" ] && return 0; sleep 0.1; done
  echo "$test_name: no bus key from the first launcher"
  cat "$1"
  exit 1
}

# wait_ready HOST COUNT: until HOST hears COUNT READY services (wrc status, csv in $work/status.csv).
wait_ready() {
  local ready=0
  for _ in $(seq 1 120); do
    on "$1" "$cli" status --format csv --duration 0.6 >"$work/status.csv" 2>/dev/null || true
    ready=$(grep -c ',READY,' "$work/status.csv" || true)
    [ "$ready" -ge "$2" ] && return 0
  done
  echo "$test_name: only $ready of $2 services READY as $1 hears them:"
  cat "$work/status.csv" "$work"/*.log
  exit 1
}

# value KEY FILE: the value after "KEY": in a summary written by wrc run (the first match).
value() { sed -n "s/^ *\"$1\": \([^,]*\),\{0,1\}$/\1/p" "$2" | head -1 | tr -d '"'; }

# The final state and counters two runs of one model must share, every digit.
state_keys=(y z roll yaw y_dot z_dot roll_dot yaw_dot spin_rate normal_force_left normal_force_right steps restarts
            contact_queries residual_evals jacobian_evals two_point_entries)

# same_state A B LABEL: every state_keys value of summary A equals B's; names each that differs.
same_state() {
  local differ=0 a b key
  for key in "${state_keys[@]}"; do
    a=$(value "$key" "$1")
    b=$(value "$key" "$2")
    if [ -z "$a" ] || [ "$a" != "$b" ]; then
      echo "$test_name: $3: $key = '$a', against '$b'"
      differ=1
    fi
  done
  return "$differ"
}
