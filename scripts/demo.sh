#!/usr/bin/env bash
# The README's main job: install what is missing, build, run the lane-change demo
# (on screen when a display is reachable, headless frames + telemetry + plots otherwise).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build=${BDFCAR_BUILD_DIR:-$root/build}
cd "$root"
exec "$build/app/bdfcar" demo "$@"
