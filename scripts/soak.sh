#!/usr/bin/env bash
# The soak (a long study, not a test): one simulated hour of driving with
# seeded, bounded random inputs and one with the flip-flop steering input,
# each through the same path as `drive --replay --batch`; prints divergences,
# non-finite samples, constraint drift and resident memory. Usage:
#   bash scripts/soak.sh [DIR]     (recordings go to DIR, default a temp folder)
#   BDFCAR_SOAK_SECONDS=600 bash scripts/soak.sh   (shorter)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BDFCAR_BUILD_DIR:-$root/build}
seconds=${BDFCAR_SOAK_SECONDS:-3600}
dir=${1:-$(mktemp -d)}
mkdir -p "$dir"
status=0
for kind in random flipflop; do
  "$build/app/bdfcar" soak --kind "$kind" --seed 1 --seconds "$seconds" --record "$dir/soak_$kind.rec" || status=$?
done
exit $status
