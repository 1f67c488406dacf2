#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# netns.sh COMMAND [ARGS...]: runs COMMAND on a private LCM bus.
# Preferred: a private network namespace (`unshare -n`, or `unshare -rn` without root) with
# loopback up, multicast on and a 224.0.0.0/4 route, so LCM's default udpm URL works there and
# nothing leaves or enters the namespace. When namespaces are not permitted, it falls back to the
# host with LCM_DEFAULT_URL on a port of its own (ttl=0: traffic stays on the host).
# Exports WRC_BUS_ISOLATION=netns|port for the command (tests skip what needs a namespace).
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: netns.sh COMMAND [ARGS...]" >&2; exit 2; }

if [ "${WRC_IN_NETNS:-}" = 1 ]; then
  ip link set lo up
  ip link set lo multicast on
  ip route add 224.0.0.0/4 dev lo
  export WRC_BUS_ISOLATION=netns
  unset WRC_IN_NETNS LCM_DEFAULT_URL
  exec "$@"
fi

self=$(readlink -f "${BASH_SOURCE[0]}")
for flags in -n -rn; do
  if unshare $flags true 2>/dev/null; then
    WRC_IN_NETNS=1 exec unshare $flags "$self" "$@"
  fi
done

# fallback: a port derived from our pid, in the dynamic range, on the host's loopback route
port=$((20000 + $$ % 40000))
echo "netns.sh: network namespaces not permitted; using udpm port $port on the host" >&2
export LCM_DEFAULT_URL="udpm://239.255.76.67:${port}?ttl=0"
export WRC_BUS_ISOLATION=port
exec "$@"
