#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job of wrc (`clients/wrc demo`), run after set-up and build by clients/wrc:
# shows what the product computes today, from the exact geometry to the contact services on the bus.
# By default the services run on a private LCM bus (a network namespace of this demo, see
# clients/lib/netns.sh); `clients/wrc demo --host-bus` uses the host's default LCM bus instead, so that
# `clients/wrc spy` in another terminal sees the traffic.
set -euo pipefail
: "${WRC_ROOT:?}" "${WRC_BUILD_DIR:?}"
wrc() { "$WRC_BUILD_DIR/clients/wrc-cli" "$@"; }

if [ "${1:-}" != "--host-bus" ] && [ "${WRC_DEMO_INNER:-}" != 1 ]; then
  WRC_DEMO_INNER=1 exec bash "$WRC_ROOT/clients/lib/netns.sh" bash "$0" "$@"
fi

section() { printf '\n=== %s\n' "$*"; }

section "Rigid-wheelset geometry, S1002 on UIC60 (EN 60E1), gauge 1435 mm, 1:40 (wrc geometry)"
echo "Both wheels touch; roll and height solved for each lateral shift. Note the jumps of the contact"
echo "point (s) onto the flange root and the flange: they are computed, not smoothed."
wrc geometry --y-from -0.008 --y-to 0.008 --y-step 0.001

section "Potential common points of the left wheel at y = 5 mm (wrc points)"
wrc points --y 0.005 --z 0.46

section "Contact area around the common point at y = 5 mm, roll 0.3 mrad (wrc area; the paper's figures 1-3)"
wrc area --y 0.005 --roll 0.0003

section "Equivalent conicity, harmonic linearisation (wrc conicity)"
wrc conicity --amplitude 0.001,0.002,0.003,0.004,0.005,0.006 --format table

section "Creep forces on one Hertzian patch, FASTSIM 20x20 vs Kalker's linear theory (wrc creep)"
for model in fastsim linear; do
  printf '%-8s ' "$model"; wrc creep --a 0.0066 --b 0.005 --normal-force 80000 --mu 0.3 --shear-modulus 8.2e10 \
    --poisson 0.28 --xi-x 0.0005 --xi-y 0.0003 --spin 0.1 --model $model | tail -1
done

section "Arnold's spline model: precomputation and accuracy (wrc fit, 10 x 2 x 2 knot intervals)"
echo "Weighted least-squares tensor-product splines over (y, roll, yaw) per wheel, fitted to the exact"
echo "geometry; the tread jumps of the common point are found, down-weighted and smoothed; flange"
echo "contact is kept. Errors against the exact geometry at points that are not samples:"
report_dir=$(mktemp -d)
wrc fit --knots 10x2x2 --report "$report_dir/fit-10x2x2.json"

section "Contact services on the bus (wrc launch, wrc status, wrc query)"
log=$(mktemp)
# The spline service gets its model from wrc-geometryd, which keeps it in a cache of this demo.
export WRC_CACHE_DIR="$report_dir/models"
# The launcher itself (not a shell function around it) runs in the background, so that $! is its
# pid and SIGTERM reaches it: it then stops every service it started.
"$WRC_BUILD_DIR/clients/wrc-cli" launch geometry contact-onepoint contact-interp contact-multipoint contact-spline dynamics pingd \
  >"$log" 2>&1 &
launcher=$!
trap 'kill -TERM $launcher 2>/dev/null || true; wait $launcher 2>/dev/null || true; rm -f "$log"; rm -rf "$report_dir/models"' EXIT
for _ in $(seq 1 30); do
  wrc status --duration 0.5 --format csv 2>/dev/null | grep -q "^geometryd,.*,READY," && break
done
echo "wrc-geometryd precomputes the spline model that the spline contact service asks it for (wrc fit --service):"
wrc fit --service --wait 300 || echo "the precomputation on wrc-geometryd failed"
ready=0
for _ in $(seq 1 60); do
  st=$(wrc status --format csv 2>/dev/null || true)
  if grep -q "multipoint.*READY" <<<"$st" && grep -q "spline.*READY" <<<"$st"; then ready=1; break; fi
done
wrc status || true
if [ "$ready" = 1 ]; then
  echo "At y = 5.2 mm the left wheel's common point jumps from the tread to the flange root: one-point"
  echo "and multi-point show it, interp smears it, the spline model's contact point lies in between."
  for model in onepoint interp multipoint spline; do
    printf '\n%s, y = 5.2 mm, rigid formulation, 77357.5 N per wheel:\n' "$model"
    wrc query --model "$model" --y 0.0052 --format table || echo "query to $model failed"
  done
  section "The paper's benchmark (wrc run: wrc-dynamicsd, SUNDIALS IDA, contact over the bus)"
  echo "S1002 on UIC60 1:40, Fz = 154715 N, Fy = 20000 N towards the right rail, V = 30 m/s, 2 s"
  echo "(parameters/benchmark.json). The one-point model's contact point chatters at the flange-root"
  echo "jump (every switch a located event and an integrator restart) until the wheel slides in rigid"
  echo "two-point contact on the switching surface; without that (--two-point-sliding false, the paper's"
  echo "one-point contact of its figures 5 and 6) it chatters, restart after restart, and stays off the"
  echo "rigid manifold; the spline model settles."
  printf '%-22s %10s %10s %9s %7s %9s %9s\n' model y[mm] yaw[mrad] wall[s] steps restarts queries
  for run in spline multipoint interp onepoint onepoint-no-sliding; do
    model=${run%%-*}
    options=()
    label=$model
    if [ "$run" = onepoint-no-sliding ]; then options=(--two-point-sliding false); label="onepoint, no sliding"; fi
    summary="$report_dir/run-$run.json"
    if wrc run --model "$model" --t-end 2 --summary "$summary" --history "$report_dir/run-$run.csv" \
        --output-period 0.002 "${options[@]}" 2>"$report_dir/run-$run.log"; then
      v() { sed -n "s/^ *\"$1\": \([^,]*\),\{0,1\}$/\1/p" "$summary" | head -1; }
      awk -v m="$label" -v y="$(v y)" -v yaw="$(v yaw)" -v w="$(v wall_time)" -v s="$(v steps)" \
          -v r="$(v restarts)" -v q="$(v contact_queries)" \
          'BEGIN { printf "%-22s %10.4f %10.4f %9.3f %7d %9d %9d\n", m, y*1e3, yaw*1e3, w, s, r, q }'
    else
      echo "$label: run failed:"; tail -3 "$report_dir/run-$run.log"
    fi
  done
  wall() { sed -n 's/^ *"wall_time": \([^,]*\),\{0,1\}$/\1/p' "$report_dir/run-$1.json" 2>/dev/null | head -1; }
  # ratio RUN LABEL NOTE: the wall time of run RUN over the spline run's, when both finished.
  ratio() {
    [ -n "$(wall "$1")" ] && [ -n "$(wall spline)" ] || return 0
    awk -v o="$(wall "$1")" -v s="$(wall spline)" -v l="$2" -v n="$3" \
      'BEGIN { printf "Wall time %s / spline: %.1f (the paper: %s)\n", l, o / s, n }'
  }
  ratio onepoint one-point "the spline model is several times faster"
  ratio onepoint-no-sliding "one-point without sliding" "spline below 0.3 of one-point"
  section "A curve with transitions on irregular track (wrc irregularities, wrc run --track --irregularities)"
  echo "parameters/track-curve-R600.json: 100 m straight, 90 m transition, R = 600 m with 130 mm cant;"
  echo "irregularities generated from the ERRI low-level spectrum (3-70 m, seed 1); 30 m/s (cant"
  echo "deficiency 99 mm), no lateral load, 8 s = 240 m: into the curve. What engineers read off each"
  echo "run, with its limits:"
  wrc irregularities --spectrum erri-low --length 300 --wavelengths 3:70 --seed 1 \
    --out "$report_dir/irregularities.csv" 2>&1 | sed 's/^/  /'
  printf '%-10s %9s %9s %10s %11s %10s %9s %9s\n' model y[mm] Y/Q_max Nadal sumY[kN] limit[kN] Tg[N] restarts
  for model in spline onepoint; do
    summary="$report_dir/curve-$model.json"
    if wrc run --model "$model" --t-end 8 --lateral-force 0 --track parameters/track-curve-R600.json \
        --irregularities "$report_dir/irregularities.csv" --summary "$summary" \
        --history "$report_dir/curve-$model.csv" --output-period 0.005 2>"$report_dir/curve-$model.log"; then
      jq -r --arg m "$model" '.run_quantities as $q | [$m, .final_state.y * 1e3,
          ([$q.y_over_q.left.max, $q.y_over_q.right.max] | max), $q.nadal_limit,
          $q.track_shift_force.max / 1e3, $q.prudhomme_limit / 1e3,
          ([$q.wear_number.left.max, $q.wear_number.right.max] | max), .counters.restarts] | @tsv' "$summary" |
        awk -F'\t' '{ printf "%-10s %9.3f %9.3f %10.3f %11.1f %10.1f %9.1f %9d\n", $1, $2, $3, $4, $5, $6, $7, $8 }'
    else
      echo "$model: curve run failed:"; tail -3 "$report_dir/curve-$model.log"
    fi
  done
  section "A vehicle on the curve: the Manchester coach (wrc run --vehicle; docs/vehicle.md)"
  echo "parameters/vehicles/manchester-coach.json: a car body on two bogies of two wheelsets each, every"
  echo "wheelset's contact from the spline service in one batch per evaluation; the same track and"
  echo "irregularities, 30 m/s, 4 s = 120 m, into the transition (further on, the stiff bogies' leading"
  echo "wheelsets run towards flange contact, outside the spline model's box: docs/vehicle.md). Per"
  echo "wheelset, and the car body's largest accelerations:"
  summary="$report_dir/coach.json"
  if wrc run --model spline --vehicle parameters/vehicles/manchester-coach.json --t-end 4 \
      --track parameters/track-curve-R600.json --irregularities "$report_dir/irregularities.csv" \
      --summary "$summary" --history "$report_dir/coach.csv" --output-period 0.005 2>"$report_dir/coach.log"; then
    printf '%-18s %9s %12s %9s %11s\n' wheelset y[mm] attack[mrad] Y/Q_max sumY[kN]
    jq -r '.vehicle.wheelsets[] | .run_quantities as $q | [.name, .final_state.y * 1e3, .final_state.yaw * 1e3,
        ([$q.y_over_q.left.max, $q.y_over_q.right.max] | max), $q.track_shift_force.max / 1e3] | @tsv' "$summary" |
      awk -F'\t' '{ printf "%-18s %9.3f %12.3f %9.3f %11.1f\n", $1, $2, $3, $4, $5 }'
    jq -r '.vehicle.accelerations[] | select(.name == "car_body") |
        "car body: largest lateral acceleration \(.lateral.max * 1000 | round / 1000) m/s^2, vertical \(.vertical.max * 1000 | round / 1000) m/s^2"' "$summary"
    jq -r '"wall time \(.wall_time * 100 | round / 100) s for \(.t_end) s simulated; \(.counters.contact_queries) contact batches of \(.counters.contact_configurations) configurations"' "$summary"
  else
    echo "coach run failed:"; tail -3 "$report_dir/coach.log"
  fi
  echo "The whole 1 km curve (parameters/track-curve-R600-1km.json, 1050 m of the same spectrum, seed 1):"
  echo "the spline model fitted over flange contact too (--box -0.012:0.012,0.004,0.005 --knots 20x4x2),"
  echo "in-process (the spline services fit the tread's box), at a track run's tolerances (docs/track.md):"
  wrc irregularities --spectrum erri-low --length 1050 --wavelengths 3:70 --seed 1 \
    --out "$report_dir/irregularities-1km.csv" 2>&1 | sed 's/^/  /'
  summary="$report_dir/coach-1km.json"
  if wrc run --model spline --in-process --vehicle parameters/vehicles/manchester-coach.json --t-end 33.7 \
      --track parameters/track-curve-R600-1km.json --irregularities "$report_dir/irregularities-1km.csv" \
      --box -0.012:0.012,0.004,0.005 --knots 20x4x2 --rtol 1e-4 --position-tolerance 1e-6 \
      --velocity-tolerance 1e-4 --summary "$summary" --history "$report_dir/coach-1km.csv" --output-period 0.01 \
      2>"$report_dir/coach-1km.log"; then
    printf '%-18s %9s %12s %9s\n' wheelset Y/Q_max Y/Q_2m_max sumY[kN]
    jq -r '.vehicle.wheelsets[] | .run_quantities as $q | [.name, ([$q.y_over_q.left.max, $q.y_over_q.right.max] | max),
        ([$q.y_over_q_2m.left.max, $q.y_over_q_2m.right.max] | max), $q.track_shift_force.max / 1e3] | @tsv' "$summary" |
      awk -F'\t' '{ printf "%-18s %9.3f %12.3f %9.1f\n", $1, $2, $3, $4 }'
    jq -r '"wall time \(.wall_time * 100 | round / 100) s for \(.t_end) s simulated (\(.t_end / .wall_time * 10 | round / 10) times real time), \(.counters.steps) steps"' "$summary"
  else
    echo "whole-curve coach run failed:"; tail -3 "$report_dir/coach-1km.log"
  fi
else
  echo "the contact services did not report READY; launcher log:"; cat "$log"
fi
kill -TERM $launcher 2>/dev/null || true
wait $launcher 2>/dev/null || true
section "Launcher log"
cat "$log"

section "Hunting stability: linear critical speed (wrc stability; docs/stability.md)"
echo "The benchmark wheelset's yaw springs (1.5e7 N/m per box) keep it stable at every speed; with"
echo "soft ones (--longitudinal-stiffness 1e6) it hunts above the linear critical speed:"
mkdir -p "$report_dir/figures"
wrc stability --model onepoint --speeds 10:120:10 --longitudinal-stiffness 1e6 \
  --out "$report_dir/stability.csv" --plot "$report_dir/figures/stability.png" 2>&1 |
  sed -n '/V \[m\/s\]/,/linear critical speed/p' | sed 's/^/  /'

section "A bogie's hunting diagram (wrc bifurcation --vehicle; docs/vehicle.md, \"Hunting of a vehicle\")"
echo "The Cooperrider bogie (parameters/vehicles/cooperrider-bogie.json) on a cone of conicity 0.2 on a"
echo "circular rail head with friction 10: a geometry whose hunting is linear, so the nonlinear critical"
echo "speed the ramp-down and its bisection find must be the linear one of the bogie's eigenvalues"
echo "(docs/vehicle.md has the diagram on S1002/UIC60):"
wrc bifurcation --model onepoint --vehicle parameters/vehicles/cooperrider-bogie.json --wheel conic:0.2 \
  --rail circle:0.1 --gauge 1.5 --gauge-depth 0 --inclination none --r0 0.425 --friction 10 --speeds 75:90:5 \
  --start-amplitude 1e-6 --disturbance 1e-6 --centred-amplitude 1e-8 --settle-time 2 --window 1 --max-time 2 \
  --speed-tolerance 0.25 --out "$report_dir/bogie-bifurcation.csv" \
  --plot "$report_dir/figures/bogie-bifurcation.png" 2>&1 | sed -n '/critical speed/p' | sed 's/^/  /'

echo "The same bogie on S1002/UIC60 1:40 (friction 0.15) with the spline model: its centred state is stable"
echo "to 111 m/s, yet a tread cycle exists far below, down to its fold, the nonlinear critical speed"
echo "(docs/vehicle.md, \"The Cooperrider car and bogie on S1002/UIC60 1:40\", has all four models and the car):"
wrc bifurcation --model spline --vehicle parameters/vehicles/cooperrider-bogie.json --r0 0.425 --friction 0.15 \
  --speeds 40:80:10 --start-amplitude 2e-3 --max-time 6 --speed-tolerance 1 \
  --out "$report_dir/bogie-s1002-bifurcation.csv" --plot "$report_dir/figures/bogie-s1002-bifurcation.png" 2>&1 |
  sed -n '/^branch\|^ramp-down\|^refinement\|critical speed/p' | sed 's/^/  /'

section "A small sweep on both cores (wrc sweep; docs/sweep.md)"
echo "The benchmark (Fy = 20 kN) at four speeds with the one-point and the spline model, 1 s each, every"
echo "run a process of its own, two at a time: the same lateral balance at every speed, the spline model"
echo "without the one-point model's restarts:"
if wrc sweep --grid model=onepoint,spline --grid speed=10,20,30,40 --extract final,counters \
    --out "$report_dir/sweep.csv" --plot "$report_dir/figures/sweep.png" --plot-x speed \
    --plot-y final_state.y --plot-by model -- --t-end 1 2>"$report_dir/sweep.log"; then
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i
                     printf "  %-10s %10s %-9s %9s %9s %9s\n", "model", "speed[m/s]", "status", "y[mm]", "restarts", "queries"
                     next }
           { printf "  %-10s %10s %-9s %9.4f %9d %9d\n", $c["model [-]"], $c["speed [m/s]"], $c["status [-]"],
                    $c["final_state.y [m]"] * 1e3, $c["counters.restarts [-]"], $c["counters.contact_queries [-]"] }' \
    "$report_dir/sweep.csv"
else
  echo "sweep failed:"; tail -3 "$report_dir/sweep.log"
fi

section "The paper's figures and the contact-geometry plots (wrc plot)"
figures="$report_dir/figures"
mkdir -p "$figures"
plot() { local name=$1; shift; if wrc plot "$@" --out "$figures/$name.png" >/dev/null 2>"$figures/$name.log"; then
  echo "  $name.png"; rm -f "$figures/$name.log"; else echo "  $name: $(tail -1 "$figures/$name.log")"; fi; }
plot fig1-distance distance --y 0.0052 --roll -0.0003
plot fig1-area area --y 0.0052 --roll -0.0003 --spline
plot fig4-displacement displacement
runs=()
for model in onepoint spline; do [ -s "$report_dir/run-$model.csv" ] && runs+=("$report_dir/run-$model.csv"); done
[ "${#runs[@]}" -gt 0 ] && plot fig5-6-run run "${runs[@]}"
runs=()
for run in onepoint-no-sliding spline; do [ -s "$report_dir/run-$run.csv" ] && runs+=("$report_dir/run-$run.csv"); done
[ "${#runs[@]}" -gt 1 ] && plot fig5-6-run-no-sliding run "${runs[@]}"
curves=()
for model in onepoint spline; do [ -s "$report_dir/curve-$model.csv" ] && curves+=("$report_dir/curve-$model.csv"); done
if [ "${#curves[@]}" -gt 0 ]; then
  plot curve-run run "${curves[@]}"
  plot curve-forces run --forces "${curves[@]}"
fi
[ -s "$report_dir/irregularities.csv" ] && plot irregularities irregularities "$report_dir/irregularities.csv"
[ -s "$report_dir/coach.csv" ] && plot coach-wheelsets wheelsets "$report_dir/coach.csv"
[ -s "$report_dir/coach-1km.csv" ] && plot coach-1km-wheelsets wheelsets "$report_dir/coach-1km.csv"
plot geometry geometry --y-from -0.008 --y-to 0.008
plot conicity conicity --a-to 0.008
plot profiles profiles --y 0.005
echo
echo "The spline model's accuracy report: $report_dir/fit-10x2x2.json"
echo "Run summaries: $report_dir/run-<model>.json (run-onepoint-no-sliding.json: without two-point sliding); stability and sweep: $report_dir/stability.csv, $report_dir/sweep.csv"
echo "Figures: $figures"
