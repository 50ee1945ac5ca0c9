#!/usr/bin/env bash
# The README's test command: install what is missing, build, run every test.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build=${BDFCAR_BUILD_DIR:-$root/build}
cd "$build"
ctest --output-on-failure -j 2 --timeout 600
