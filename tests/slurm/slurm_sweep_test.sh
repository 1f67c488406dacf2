#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# slurm_sweep_test.sh WRC_CLI: `wrc sweep --slurm` against a real single-node Slurm, and the same
# sweep run locally: the two CSVs must be the same (every column but wall_time [s]).
#
# The test starts its own cluster on loopback and stops exactly what it started (by pid): Debian's
# munged with a key and socket of its own, slurmctld and slurmd in the foreground (-D) with a
# slurm.conf for one node (this host, at 127.0.0.1, as many CPUs as it has), spool and state in a
# temporary directory, SlurmUser root, proctrack/linuxproc, no cgroups, no accounting, both daemons
# bound to 127.0.0.1 (CommunicationParameters=NoInAddrAny), on ports that were free. Not in a private
# network namespace: with loopback alone there, getaddrinfo's AI_ADDRCONFIG finds no address and
# Slurm 22.05 cannot open its ports.
# Skips (exit 77) when slurm-wlm or munge are not installed or when not root (slurmd must be).
set -euo pipefail
cli=${1:?usage: slurm_sweep_test.sh WRC_CLI}
skip() { echo "SKIP: $*"; exit 77; }
for tool in munged slurmctld slurmd sbatch squeue sinfo; do
  command -v "$tool" >/dev/null || skip "$tool is not installed (Debian packages slurm-wlm and munge; clients/lib/setup.sh installs them)"
done
[ "$(id -u)" = 0 ] || skip "slurmd must run as root to start jobs"

now_ms() { echo $(($(date +%s%N) / 1000000)); }
seconds_since() { local ms=$(($(now_ms) - $1)); printf "%d.%01d" $((ms / 1000)) $((ms % 1000 / 100)); }
started=$(now_ms)
dir=$(mktemp -d /tmp/wrc-slurm-test.XXXXXX)
pids=()
cleanup() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  if [ "$status" != 0 ] && [ "$status" != 77 ]; then
    echo "--- slurmctld.log"; tail -n 20 "$dir/slurmctld.log" 2>/dev/null || true
    echo "--- slurmd.log"; tail -n 20 "$dir/slurmd.log" 2>/dev/null || true
    echo "--- task logs"; tail -n 20 "$dir"/slurm.csv.work/logs/* 2>/dev/null || true
  fi
  rm -rf "$dir"
  exit "$status"
}
trap cleanup EXIT

# Two free ports on loopback (a connection refused: nothing listens there).
free_port() {
  local p
  while :; do
    p=$((20000 + RANDOM % 30000))
    (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return; }
  done
}
ctld_port=$(free_port)
slurmd_port=$(free_port)
[ "$ctld_port" != "$slurmd_port" ] || slurmd_port=$((ctld_port + 1))

# munge: its own key (1 KiB, readable by root only), socket, pid and log.
dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge.key"
munged --foreground --force --socket="$dir/munge.socket" --key-file="$dir/munge.key" \
  --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" >"$dir/munged.out" 2>&1 &
pids+=($!)

host=$(hostname -s)
mkdir -p "$dir/state" "$dir/spool"
cat >"$dir/slurm.conf" <<CONF
ClusterName=wrctest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerParameters=sched_interval=1
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
CommunicationParameters=NoInAddrAny
ReturnToService=2
MinJobAge=300
KillWait=5
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=wrc Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"
for _ in $(seq 50); do [ -S "$dir/munge.socket" ] && break; sleep 0.1; done
slurmctld -D -f "$SLURM_CONF" >"$dir/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$dir/slurmd.out" 2>&1 &
pids+=($!)
state=
deadline=$(($(now_ms) + 30000))
while [ "$(now_ms)" -lt "$deadline" ]; do
  state=$(timeout 5 sinfo --noheader --format=%T 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "$state" = idle ] || { echo "FAIL: the node is not idle after 30 s (sinfo: '$state')"; exit 1; }
echo "slurm: node $host idle after $(seconds_since "$started") s (slurmctld port $ctld_port, slurmd $slurmd_port)"

# Six short runs of the benchmark wheelset: speed x initial shift, one initial shift (30 mm) with
# the flange climbed at the start (a failed row with its error, in both CSVs).
sweep=(--grid speed=20,30 --grid y0=0,0.002,0.03 --extract final,maxima,counters
       -- --model onepoint --t-end 0.1)
cd "$dir"
"$cli" sweep --out local.csv --jobs 2 "${sweep[@]}" 2>local.err || { cat local.err; exit 1; }
"$cli" sweep --out slurm.csv --slurm --array-limit 2 "${sweep[@]}" 2>slurm.err || { cat slurm.err; exit 1; }
grep -q "Slurm job" slurm.err || { echo "FAIL: no Slurm job submitted"; cat slurm.err; exit 1; }
rows=$(($(wc -l <slurm.csv) - 1))
[ "$rows" = 6 ] || { echo "FAIL: $rows rows in the Slurm CSV, expected 6"; cat slurm.csv; exit 1; }
finished=$(grep -c ',finished,' slurm.csv || true)
failed=$(grep -c ',failed,' slurm.csv || true)
[ "$finished" = 4 ] && [ "$failed" = 2 ] || { echo "FAIL: $finished finished and $failed failed rows, expected 4 and 2"; cat slurm.csv; exit 1; }
"$cli" sweep --compare local.csv slurm.csv || { echo "FAIL: the local and the Slurm CSV differ"; exit 1; }
ls slurm.csv.work/logs/slurm-*_*.log >/dev/null || { echo "FAIL: no Slurm task logs"; exit 1; }
# Submitted without waiting, gathered later from the work directory alone (exit 1 while rows are missing).
"$cli" sweep --out later.csv --slurm --no-wait "${sweep[@]}" 2>later.err || { cat later.err; exit 1; }
deadline=$(($(now_ms) + 60000))
until "$cli" sweep --out later.csv --gather 2>gather.err; do
  [ "$(now_ms)" -lt "$deadline" ] || { cat gather.err; echo "FAIL: --gather incomplete after 60 s"; exit 1; }
  sleep 0.5
done
"$cli" sweep --compare local.csv later.csv || { echo "FAIL: the gathered CSV differs from the local one"; exit 1; }
sed "s/^/  /" slurm.err
echo "PASS: the Slurm sweep's CSV is the local one's ($rows rows, $finished finished, $failed failed); $(seconds_since "$started") s in all"
