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
# The Python package where Debian's python3 finds it (`import bdfcar` with no
# path set): the README's build only, not the other flavours' folders.
if [ -z "${BDFCAR_BUILD_DIR:-}" ] && grep -q '^BDFCAR_PYTHON_INSTALL_DIR:' "$build/CMakeCache.txt"; then
  site=$(sed -n 's/^BDFCAR_PYTHON_INSTALL_DIR:PATH=//p' "$build/CMakeCache.txt")
  parent=$site
  while [ ! -e "$parent" ]; do parent=$(dirname "$parent"); done
  if [ -w "$parent" ]; then
    cmake --install "$build" --component python >/dev/null
    echo "build: the bdfcar Python module is installed in $site"
    # A python3 ahead of Debian's on the PATH (pyenv, a virtual environment)
    # does not look there: say which interpreter has it.
    built=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt")
    onPath=$(command -v python3 || true)
    if [ -n "$built" ] && [ -n "$onPath" ] && [ "$(readlink -f "$onPath")" != "$(readlink -f "$built")" ] &&
       ! "$onPath" -c "import sys; sys.exit(0 if sys.prefix == '/usr' else 1)" 2>/dev/null; then
      echo "build: python3 on the PATH is $onPath, not $built the module is built for: run $built -c 'import bdfcar'"
    fi
  else
    echo "build: $site is not writable: use PYTHONPATH=$build/python (or run as root)"
  fi
fi
