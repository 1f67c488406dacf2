#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# local_sweep_test.sh WRC_CLI: `wrc sweep` on this machine, end to end: mistakes refused before
# anything runs (naming the key, the point or the option), a 2x2 grid with two failing runs (rows
# with their error), the CSV's columns, resuming (a cut CSV is completed to the same table, a
# complete one runs nothing), another sweep's CSV or work directory refused, an interrupted sweep
# resumed, a sweep on a track layout without the parameters' lateral load, and the plot of the CSV.
set -euo pipefail
cli=${1:?usage: local_sweep_test.sh WRC_CLI}
track="$(cd "$(dirname "$0")/../.." && pwd)/parameters/track-curve-R600.json"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
# expect_error TEXT COMMAND...: the command fails and its stderr names TEXT.
expect_error() {
  local text=$1
  shift
  if "$@" >out.txt 2>err.txt; then fail "'$*' succeeded"; fi
  grep -qF -- "$text" err.txt || { cat err.txt; fail "'$*' did not say '$text'"; }
}

expect_error "--grid speeed: not a key a run takes" "$cli" sweep --grid speeed=1 -- --model onepoint
expect_error "grid point 0 (speed = -5)" "$cli" sweep --grid speed=-5,10 -- --model onepoint
expect_error "is also the grid key speed" "$cli" sweep --grid speed=10 -- --model onepoint --speed 20
expect_error "a sweep sets it itself" "$cli" sweep --grid speed=10 -- --model onepoint --summary s.json
expect_error "--grid 'speed=40:10:10': range 40:10:10: TO is below FROM" "$cli" sweep --grid speed=40:10:10 -- --model onepoint
expect_error "--extract nothing: neither a group" "$cli" sweep --grid speed=10 --extract nothing -- --model onepoint
expect_error "--model is required" "$cli" sweep --grid speed=10
[ ! -e sweep.csv ] || fail "a refused sweep wrote sweep.csv"

# y0 = 0.03 m: the flange has climbed at the start, a failed row with its reason.
grid=(--grid speed=20,30 --grid y0=0,0.03 -- --model onepoint --t-end 0.1)
"$cli" sweep --jobs 2 --out a.csv "${grid[@]}" 2>err.txt || { cat err.txt; fail "the sweep failed"; }
[ "$(wc -l <a.csv)" = 5 ] || { cat a.csv; fail "not 4 rows"; }
head -1 a.csv | grep -q '^point \[-\],speed \[m/s\],y0 \[m\],status \[-\],final_state.y \[m\],' || fail "header: $(head -1 a.csv)"
head -1 a.csv | grep -q 'run_quantities.y_over_q.left.max \[-\]' || fail "no Y/Q column"
head -1 a.csv | grep -q 'counters.steps \[-\].*,error \[-\],wall_time \[s\]$' || fail "no steps, error, wall_time columns"
[ "$(grep -c '^[0-9]*,[0-9]*,0,finished,' a.csv)" = 2 ] || { cat a.csv; fail "y0 = 0 did not finish twice"; }
[ "$(grep -c '^[0-9]*,[0-9]*,0.03,failed,' a.csv)" = 2 ] || { cat a.csv; fail "y0 = 0.03 did not fail twice"; }
awk -F, 'NR > 1 { print $1 }' a.csv | tr '\n' ' ' | grep -qx '0 1 2 3 ' || fail "rows not in grid order"

# Resume: the first two rows kept, the other two run again; the table is the same.
head -3 a.csv >b.csv
"$cli" sweep --jobs 2 --out b.csv --work-dir b.work "${grid[@]}" 2>err.txt || { cat err.txt; fail "resume failed"; }
grep -q "4 runs, 2 already done (2 in b.csv, 0 more in" err.txt || { cat err.txt; fail "did not resume from 2 rows"; }
"$cli" sweep --compare a.csv b.csv >/dev/null || fail "the resumed CSV differs: $("$cli" sweep --compare a.csv b.csv)"
"$cli" sweep --jobs 2 --out b.csv --work-dir b.work "${grid[@]}" 2>err.txt || fail "second resume failed"
grep -q ", 0 to run" err.txt || { cat err.txt; fail "a complete sweep ran again"; }

# Another sweep: its work directory, then its CSV, refused.
other=(--grid speed=20,30 --grid friction=0.2 -- --model onepoint --t-end 0.1)
expect_error "holds another sweep" "$cli" sweep --out a.csv "${other[@]}"
expect_error "a.csv is the CSV of another sweep: its column 3 is 'y0 [m]' where this sweep has 'friction [-]'" \
  "$cli" sweep --out a.csv --work-dir other.work "${other[@]}"

# Interrupted after the first rows (SIGINT, as Ctrl-C): exit 130, the rows so far kept, a rerun completes.
slow=(--grid speed=10,15,20,25,30,35 -- --model onepoint --t-end 0.6)
"$cli" sweep --jobs 1 --out c.csv "${slow[@]}" 2>err.txt &
pid=$!
for _ in $(seq 600); do [ "$(cat c.csv 2>/dev/null | wc -l)" -ge 2 ] && break; sleep 0.05; done
kill -INT "$pid"
status=0
wait "$pid" || status=$?
[ "$status" = 130 ] || { cat err.txt; fail "an interrupted sweep exited with $status, not 130"; }
kept=$(($(wc -l <c.csv) - 1))
[ "$kept" -ge 1 ] && [ "$kept" -lt 6 ] || { cat c.csv; fail "$kept rows after the interrupt"; }
pgrep -f -- "--work-dir $dir/c.csv.work" >/dev/null && fail "a run of the interrupted sweep is still running"
"$cli" sweep --jobs 2 --out c.csv "${slow[@]}" 2>err.txt || { cat err.txt; fail "the resumed sweep failed"; }
[ "$(grep -c ',finished,' c.csv)" = 6 ] || { cat c.csv; fail "the resumed sweep has not 6 finished rows"; }

# On a track layout the runs take no lateral load from the parameters (the benchmark's -20 kN, a
# --params file's), and the sweep says so once; an explicit --lateral-force (here the grid key) keeps its value.
echo '{"lateral_force": -5000}' >loaded.json
"$cli" sweep --jobs 2 --out d.csv --grid speed=20,30 --extract parameters.lateral_force \
  -- --model interp --t-end 0.05 --track "$track" 2>err.txt || { cat err.txt; fail "the track sweep failed"; }
grep -qF "sweep: every run: lateral load: -20000 N of the parameters set to 0 (a track layout's curves" err.txt ||
  { cat err.txt; fail "the track sweep did not say that the lateral load is 0"; }
[ "$(grep -c ',finished,0,' d.csv)" = 2 ] || { cat d.csv; fail "a track sweep's run kept the benchmark's lateral load"; }
"$cli" sweep --jobs 2 --out e.csv --grid lateral_force=-1000,0 --extract parameters.lateral_force \
  -- --model interp --t-end 0.05 --track "$track" --params loaded.json 2>err.txt || { cat err.txt; fail "the lateral_force sweep failed"; }
grep -q "lateral load:" err.txt && { cat err.txt; fail "a sweep with --lateral-force said the lateral load is 0"; }
awk -F, 'NR > 1 { print $2 "=" $4 }' e.csv | tr '\n' ' ' | grep -qx -- '-1000=-1000 0=0 ' || { cat e.csv; fail "--lateral-force not kept"; }
"$cli" sweep --jobs 2 --out f.csv --grid speed=20 --extract parameters.lateral_force \
  -- --model interp --t-end 0.05 --track "$track" --params loaded.json 2>err.txt || { cat err.txt; fail "the --params sweep failed"; }
grep -qF "lateral load: -5000 N of the parameters set to 0" err.txt || { cat err.txt; fail "a --params lateral load was kept"; }
[ "$(grep -c ',finished,0,' f.csv)" = 1 ] || { cat f.csv; fail "a --params file's lateral load was kept on a track"; }

# The plot of a CSV.
"$cli" plot sweep a.csv --y final_state.y --x speed --by y0 --out a.png >/dev/null
[ -s a.png ] || fail "no plot"
expect_error "--y nothing: no such column" "$cli" plot sweep a.csv --y nothing --out x.png
echo "PASS: local sweep (refusals, failed rows, resume, interrupt, track without lateral load, plot)"
