#!/usr/bin/env bash
# Builds every target with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DBDFCAR_SANITIZE=ON, RelWithDebInfo at -O1) in build-asan/ (or
# $BDFCAR_BUILD_DIR) and runs the whole ctest suite under them.
# The allocation-counting tests are not built (ASan owns the allocator), see
# tests/CMakeLists.txt. Usage: scripts/sanitize.sh [extra ctest arguments]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-deps.sh"
build=${BDFCAR_BUILD_DIR:-$root/build-asan}
jobs=${BDFCAR_JOBS:-2}

start=$(date +%s)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBDFCAR_SANITIZE=ON
else
  cmake "$build" >/dev/null
fi
cmake --build "$build" -j "$jobs"
built=$(date +%s)

# halt_on_error + -fno-sanitize-recover=all: the first report fails the test.
# detect_leaks: LeakSanitizer at exit, with third-party-only suppressions.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:print_stacktrace=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"

cd "$build"
# Tests keep their 300 s limit (tests/CMakeLists.txt): at -O1 the slowest
# one needs a small fraction of it under ASan. Nothing is excluded.
set +e
ctest --output-on-failure -j "$jobs" --timeout 600 "$@" 2>&1 | tee "$build/sanitize-ctest.log"
rc=${PIPESTATUS[0]}
set -e
end=$(date +%s)
summary=$(grep -E '^[0-9]+% tests passed' "$build/sanitize-ctest.log" | tail -1)
skipped=$(grep -cE '^\s+[0-9]+ - .*\(Skipped\)' "$build/sanitize-ctest.log" || true)
line="sanitize: ${summary:-no ctest summary} ($skipped skipped); build $((built - start)) s, tests $((end - built)) s (ASan+UBSan+float-cast-overflow, -O1, $(date -u +%F))"
echo "$line"
echo "$line" > "$build/sanitize-summary.txt"  # read by scripts/report.sh
exit "$rc"
