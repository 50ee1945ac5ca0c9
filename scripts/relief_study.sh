#!/usr/bin/env bash
# Where a relief case's Newton iterations come from (issue 26's cost target;
# a study, not a test): the case with the default policy and with one thing
# changed at a time (the Jacobian's age, the ground held through the step,
# the refinement, a fixed shorter step, the road's amplitude), each with its
# Newton iterations per 10 ms of the window [T1, T2] (a run to T2 less one
# to T1: settling and start-up cancel), its stalled steps, and its distance
# to the same case converged at 1 ms (Newton to tolerance, the Jacobian
# every step; the measure of RESULTS 5d: RMS of yaw rate and lateral
# acceleration as % of the converged run's peak, the wheel loads as % of
# each one's swing, the largest of the four; a straight run's RMS absolute).
# Usage:
#   bash scripts/relief_study.sh [SCENARIO] [T1] [T2]
#   (default assets/scenarios/hard/rough_lane_change.toml 2 5)
set -euo pipefail
if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
  exit 0
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BDFCAR_BUILD_DIR:-$root/build}
scenario=${1:-$root/assets/scenarios/hard/rough_lane_change.toml}
t1=${2:-2}
t2=${3:-5}
bdfcar=$build/app/bdfcar
[ -x "$bdfcar" ] || { echo "relief_study: $bdfcar is not built (bash scripts/build.sh)" >&2; exit 2; }
[ -f "$scenario" ] || { echo "relief_study: no scenario file $scenario" >&2; exit 2; }
awk -v a="$t1" -v b="$t2" 'BEGIN { exit !(a + 0 == a && b + 0 == b && a > 0 && b > a) }' ||
  { echo "relief_study: the window T1 T2 must be seconds with 0 < T1 < T2 (got '$t1' '$t2')" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A run's summary line to T (`bdfcar run` prints one).
summary() {  # summary T ARGS...
  local t=$1
  shift
  "$bdfcar" run "$scenario" --duration "$t" "$@" | tail -n 1
}
field() { sed -nE "s/.*[( ]([0-9]+) $1.*/\1/p"; }  # field NAME: the count before NAME
# The case converged on the variant's terrain, once per terrain: its file
# name, or "own" for the scenario's.
converged() {  # converged KEY TERRAIN_ARGS...
  local key=$1
  shift
  [ -f "$tmp/converged_$key.csv" ] && return 0
  echo "converged run on $key terrain (1 ms, Newton to tolerance, Jacobian every step)..." >&2
  "$bdfcar" run "$scenario" --duration "$t2" --set integrator.step=0.001 --set integrator.newton_iterations=0 \
    --set integrator.jacobian_every=1 "$@" --out "$tmp/converged_$key.csv" > /dev/null
}

# The road's amplitude: the terrain file's rms_height lines scaled (a
# terrain without them, or one whose copy cannot be read from elsewhere,
# gives no rows for it).
terrainOf=$(sed -nE 's/^ *terrain *= *"([^"]+)".*/\1/p' "$scenario" | head -n 1)
terrain=""
if [ -n "$terrainOf" ]; then
  case $terrainOf in /*) terrain=$terrainOf ;; *) terrain=$(dirname "$scenario")/$terrainOf ;; esac
fi

variants=("the default policy|")
variants+=("the Jacobian every step, whole|--set integrator.jacobian_every=1 --set integrator.jacobian_slices=1")
variants+=("the ground held where the predictor put the wheel (ground_inside_step = false)|--set scenario.ground_inside_step=false")
variants+=("no refinement (refine_error = 0)|--set integrator.refine_error=0")
variants+=("5 ms steps, no refinement|--set integrator.step=0.005 --set integrator.refine_error=0")
if [ -n "$terrain" ] && grep -qE '^ *rms_height *=' "$terrain"; then
  for scale in 0.5 0.25 0.125; do
    awk -v s="$scale" '/^ *rms_height *=/ { split($0, kv, "="); printf "rms_height = %.6g\n", s * kv[2]; next } { print }' \
      "$terrain" > "$tmp/terrain_$scale.toml"
    variants+=("the road's rms height x $scale|--set scenario.terrain=$tmp/terrain_$scale.toml")
  done
fi
[ -f "$root/assets/terrain/flat.toml" ] && variants+=("flat.toml (the same tyres, driver and policy)|--set scenario.terrain=$root/assets/terrain/flat.toml")

echo "| $(basename "$scenario"), $t1-$t2 s | Newton iterations per 10 ms | refreshed / rescued / refined steps | yaw rate / lateral acceleration, % of peak | load, % of swing |"
echo "|---|---|---|---|---|"
for v in "${variants[@]}"; do
  name=${v%%|*}
  read -r -a args <<< "${v#*|}"
  key=own
  terrainArgs=()
  for arg in "${args[@]}"; do
    case $arg in scenario.terrain=*) key=$(basename "${arg#scenario.terrain=}" .toml); terrainArgs=(--set "$arg") ;; esac
  done
  converged "$key" "${terrainArgs[@]}"
  if ! a=$(summary "$t1" "${args[@]}" 2> "$tmp/err") || ! b=$(summary "$t2" "${args[@]}" --out "$tmp/run.csv" 2> "$tmp/err"); then
    echo "| $name | failed: $(head -c 200 "$tmp/err" | tr '\n' ' ') | | | |"
    continue
  fi
  per10=$(awk -v a="$(field 'Newton iterations' <<< "$a")" -v b="$(field 'Newton iterations' <<< "$b")" -v t1="$t1" -v t2="$t2" \
    'BEGIN { printf "%.2f", (b - a) / ((t2 - t1) / 0.01) }')
  stalls="$(field refreshed <<< "$b") / $(field rescued <<< "$b") / $(field refined <<< "$b")"
  distance=$(python3 - "$tmp/converged_$key.csv" "$tmp/run.csv" <<'EOF'
import csv, math, sys
def rows(path):
    with open(path, newline="") as f:
        return {round(float(r["time_s"]), 4): r for r in csv.DictReader(f)}
ref, run = rows(sys.argv[1]), rows(sys.argv[2])
times = [t for t in run if t in ref and t >= 0]
def rms(key):
    return math.sqrt(sum((float(run[t][key]) - float(ref[t][key])) ** 2 for t in times) / len(times))
def peak(key):
    return max(abs(float(ref[t][key])) for t in times)
# A straight run (a converged peak yaw rate under 0.05 rad/s, as in 5d) has
# no peak to divide by: its RMS then, absolute.
if peak("yawrate_radps") >= 0.05:
    turn = "%.2f / %.2f" % tuple(100 * rms(k) / peak(k) for k in ("yawrate_radps", "ay_mps2"))
else:
    turn = "straight: %.2g rad/s / %.2g m/s^2" % (rms("yawrate_radps"), rms("ay_mps2"))
loads = []
for w in ("FL", "FR", "RL", "RR"):
    k = "Fz_%s_N" % w
    swing = max(float(ref[t][k]) for t in times) - min(float(ref[t][k]) for t in times)
    loads.append(100 * rms(k) / swing if swing > 0 else 0.0)
print("%s | %.2f" % (turn, max(loads)))
EOF
)
  echo "| $name | $per10 | $stalls | $distance |"
done
