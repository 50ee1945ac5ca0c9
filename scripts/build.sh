#!/usr/bin/env bash
# Configures (once) and builds bdfcar: Release with debug info, 2 jobs.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BDFCAR_BUILD_DIR:-$root/build}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo
else
  cmake "$build" >/dev/null  # re-configure if a previous configure failed or files changed
fi
cmake --build "$build" -j "${BDFCAR_JOBS:-2}" "$@"
