#!/usr/bin/env bash
# The planar rung beside LFDM's 18-DOF model (issue 25), on this machine, in
# one run: both step a lane change at 80 km/h with a 10 ms step; the median
# time per step of 5 runs each and their ratio. Fetches nothing: give it the
# root of an LFDM source tree (github.com/uwsbel/low-fidelity-dynamic-models,
# cloned by you) and it compiles its 18-DOF model with a small timing driver
# (tools/lfdm/lfdm_step_time.cpp); without one it says so and exits 0.
#
#   bash scripts/lfdm_side_by_side.sh [LFDM_SOURCE_DIR]   (or LFDM_DIR=...)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BDFCAR_BUILD_DIR:-$root/build}
lfdm=${1:-${LFDM_DIR:-}}
if [ "${lfdm:-}" = "-h" ] || [ "${lfdm:-}" = "--help" ]; then
  sed -n 2,9p "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  exit 0
fi

# bdfcar's planar rung: the p50 per-step time `run` prints, median of 5 runs.
bdfcar() {
  for _ in 1 2 3 4 5; do
    "$build/app/bdfcar" run "$root/assets/scenarios/lane_change.toml" --fidelity planar 2>&1 |
      sed -nE 's/.*\(p50 ([0-9.]+),.*/\1/p'
  done | sort -g | sed -n 3p
}
ours=$(bdfcar)
echo "bdfcar planar (lane_change.toml, 10 ms): ${ours} us per step (median of 5 runs of the p50)"

if [ -z "${lfdm:-}" ]; then
  echo "LFDM: not given (bash scripts/lfdm_side_by_side.sh LFDM_SOURCE_DIR, or LFDM_DIR=...): no side-by-side figure"
  exit 0
fi
models="$lfdm/wheeled_vehicle_models"
src="$models/18dof"
for f in "$src/dof18.cpp" "$src/dof18_halfImplicit.cpp" "$models/utils/utils.cpp" "$src/data/json/Sedan/vehicle.json"; do
  if [ ! -f "$f" ]; then
    echo "LFDM: $lfdm is not an LFDM source tree (no $f)" >&2
    exit 2
  fi
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
g++ -std=c++17 -O3 -march=native -w -I"$src" -I"$models/utils" -I"$models/third_party" \
  "$root/tools/lfdm/lfdm_step_time.cpp" "$src/dof18.cpp" "$src/dof18_halfImplicit.cpp" "$models/utils/utils.cpp" \
  -o "$tmp/lfdm_step_time"
theirs=$("$tmp/lfdm_step_time" "$src/data/json/Sedan/vehicle.json" "$src/data/json/Sedan/tmeasy.json" 5 |
  awk '/lfdm18_us_per_step/ { print $2 }')
echo "LFDM 18-DOF (Sedan, half-implicit, 10 ms): ${theirs} us per step (median of 5 runs)"
awk -v a="$ours" -v b="$theirs" 'BEGIN { printf "bdfcar planar / LFDM 18-DOF, per step: %.1f\n", a / b }'
