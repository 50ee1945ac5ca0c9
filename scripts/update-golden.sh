#!/usr/bin/env bash
# Records the golden telemetry hashes of this build flavour in
# tests/data/golden_hashes.txt. Run it only when a change of the numbers is
# meant (a physics change), and say why in the commit. The other flavour's
# hashes are recorded by building it: BDFCAR_BUILD_DIR=build-generic
# BDFCAR_CMAKE_ARGS="-DBDFCAR_NATIVE_VECTOR=OFF -DBDFCAR_BUILD_GRAPHICS=OFF" bash scripts/update-golden.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BDFCAR_BUILD_DIR:-$root/build}
if [ ! -f "$build/CMakeCache.txt" ]; then
  # shellcheck disable=SC2086
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo ${BDFCAR_CMAKE_ARGS:-}
fi
cmake --build "$build" -j "${BDFCAR_JOBS:-2}" --target test_determinism
BDFCAR_UPDATE_GOLDEN=1 "$build/tests/test_determinism"
git -C "$root" diff --stat -- tests/data/golden_hashes.txt
