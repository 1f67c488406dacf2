#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The spline model over the bus in pieces, under 5 % loss (the hosts: tests/hosts/hosts.sh).
# h1 runs wrc-geometryd and a spline service `a`, which reads the model from the cache they share;
# h2, with a cache of its own, runs a spline service `b`, which cannot read that file and gets the
# model in pieces (model_piece_t), while nft drops 5 % of every datagram that reaches h2 at random.
# b must become READY with the same model hash as a, say that the model came in pieces, and the
# model file must be above 400 kB (the default fit's).
#   usage: clients/lib/netns.sh tests/hosts/model_pieces_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: model_pieces_test.sh BUILD_DIR}" && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/hosts.sh"
hosts_init "model pieces"
command -v nft >/dev/null || { echo "model pieces: no nft (nftables); skipped"; exit 77; }

bridge lan
host h1 lan 10.77.0.1
host h2 lan 10.77.0.2
on h2 nft add table inet loss
on h2 nft add chain inet loss in '{ type filter hook input priority 0; policy accept; }'
# The first two datagrams above 20 kB (pieces: nothing else is that large) are lost for sure, so
# that the missing ones must be asked for again; then 5 % of everything, at random.
on h2 nft add rule inet loss in iifname eth0 meta length '>' 20000 quota until 65536 bytes counter drop
on h2 nft add rule inet loss in iifname eth0 numgen random mod 100 lt 5 counter drop
printf 'contact-spline-b wrc-contactd --model spline --instance b\n' >"$work/b.txt"
launch_on h1 "$work/h1.log" geometry contact-spline
wait_for_key "$work/h1.log"
launch_on h2 "$work/h2.log" --profile "$work/b.txt" contact-spline-b
wait_ready h1 3

hash_of() { awk -F, -v i="$1" '$1 == "spline" && $2 == i && $4 == "READY" { print $12 }' "$work/status.csv" | head -1; }
a=$(hash_of a)
b=$(hash_of b)
if [ -z "$a" ] || [ "$a" = - ] || [ "$a" != "$b" ]; then
  echo "model pieces: model hash of a '$a', of b '$b'"
  cat "$work/status.csv"
  exit 1
fi
if ! grep -q "came in .* pieces" "$work/h2.log"; then
  echo "model pieces: b does not say that its model came in pieces:"
  cat "$work/h2.log"
  exit 1
fi
size=$(grep -o "came in .* pieces ([0-9]* B" "$work/h2.log" | head -1 | sed 's/.*(\([0-9]*\) B/\1/')
if [ "${size:-0}" -lt 400000 ]; then
  echo "model pieces: the model file has ${size:-?} B, the test needs one above 400 kB"
  exit 1
fi
requests=$(grep -o "after [0-9]* piece request" "$work/h2.log" | head -1 | tr -dc 0-9)
if [ "${requests:-0}" -lt 2 ]; then
  echo "model pieces: b asked for pieces ${requests:-?} times; with two pieces lost for sure it must ask again"
  exit 1
fi
dropped=$(on h2 nft list chain inet loss in | sed -n 's/.*counter packets \([0-9]*\).*/\1/p' | awk '{ n += $1 } END { print n + 0 }')
echo "model pieces: b READY with a's model hash $a: $(grep -o "came in .*" "$work/h2.log" | head -1);" \
  "nft dropped $dropped datagrams bound for h2; PASS"
