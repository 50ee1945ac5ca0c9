#!/usr/bin/env bash
# libFuzzer over the file loaders (fuzz/*.cpp): builds build-fuzz/ (or
# $BDFCAR_FUZZ_BUILD_DIR) with clang, ASan + UBSan, seeds each corpus from
# assets/ and runs the targets one at a time.
#   scripts/fuzz.sh [TARGET|all] [RUNS]       RUNS: executions per target (default 1000000)
# FUZZ_MAX_TIME=S caps each target's wall time in seconds (default: none).
# A finding (crash, sanitizer report, 1 s timeout, over 2 GiB, or an exception
# type the loader does not document, see fuzz/fuzz_common.h) stops its target;
# the input is kept in build-fuzz/findings/TARGET/. Exit status: 1 if any.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BDFCAR_FUZZ_BUILD_DIR:-$root/build-fuzz}
target=${1:-all}
runs=${2:-1000000}
all_targets=(fuzz_vehicle fuzz_scenario fuzz_terrain fuzz_road fuzz_obj fuzz_mapping fuzz_tir)

# The main packages, then clang and libFuzzer (a separate list).
"$root/scripts/install-deps.sh"
"$root/scripts/install-deps.sh" "$root/scripts/packages-fuzz.txt"

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DBDFCAR_FUZZ=ON -DBDFCAR_BUILD_TESTS=OFF
else
  cmake "$build" >/dev/null
fi
if [ "$target" = all ]; then targets=("${all_targets[@]}"); else targets=("$target"); fi
cmake --build "$build" -j "${BDFCAR_JOBS:-2}" --target "${targets[@]}"

# Seed corpora from assets/ (copied, never committed twice) plus a few
# synthetic files for kinds the assets lack (heightfield, mesh terrain).
seed() {
  local t=$1 dir="$build/corpus/$1"
  mkdir -p "$dir"
  case $t in
    fuzz_vehicle) cp "$root"/assets/vehicles/*.toml "$dir"/ ;;
    fuzz_scenario) cp "$root"/assets/scenarios/*.toml "$dir"/ ;;
    fuzz_terrain)
      # rough.toml (288k heightfield points x 64 waves) alone takes 2-5 s under
      # ASan, over the 1 s timeout: reported, and left out of the seeds.
      find "$root"/assets/terrain -name '*.toml' ! -name rough.toml -exec cp {} "$dir"/ \;
      printf 'kind = "heightfield"\nfriction = 0.9\n[heightfield]\nx0 = -10\ny0 = -10\ndx = 10\ndy = 10\nheights = [[0, 0, 0], [0, 0.5, 0], [0, 0, 0]]\n' >"$dir/seed_heightfield.toml"
      printf 'kind = "mesh"\nfriction = 0.9\n[mesh]\nobj = "square.obj"\noffset = [0, 0, 0]\n' >"$dir/seed_mesh.toml" ;;
    fuzz_road) grep -l 'kind = "road"' "$root"/assets/terrain/*.toml | grep -v '/rough.toml$' | xargs -I{} cp {} "$dir"/ ;;
    fuzz_obj)
      # The sedan body is 67 kB: its first vertices and faces keep inputs short.
      head -n 80 "$root/assets/models/sedan_body.obj" >"$dir/sedan_head.obj"
      printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1/1/1 2/2/2 3/3/3\nf -4 -2 -1\n' >"$dir/seed_quad.obj" ;;
    fuzz_mapping) cp "$root"/assets/input/*.toml "$dir"/ ;;
    fuzz_tir) cp "$root"/assets/tyres/*.tir "$dir"/ ;;
  esac
  # The loaders' own bad-input tests (tests/data/bad) make good seeds too.
  local bad="$root/tests/data/bad"
  case $t in
    fuzz_vehicle) cp "$bad"/vehicle_*.toml "$dir"/ 2>/dev/null || true ;;
    fuzz_scenario) cp "$bad"/scenario_*.toml "$dir"/ 2>/dev/null || true ;;
    fuzz_terrain) cp "$bad"/terrain_*.toml "$dir"/ 2>/dev/null || true ;;
    fuzz_obj) find "$bad" -maxdepth 1 -name '*.obj' -size -8k -exec cp {} "$dir"/ \; ;;
    fuzz_tir) find "$bad/parts" -maxdepth 1 -name '*.tir' -exec cp {} "$dir"/ \; ;;
  esac
}

export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:print_stacktrace=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0
summary=()
for t in "${targets[@]}"; do
  seed "$t"
  findings="$build/findings/$t"
  mkdir -p "$findings"
  log="$build/logs/$t.log"
  mkdir -p "$(dirname "$log")"
  extra=()
  [ -n "${FUZZ_MAX_TIME:-}" ] && extra+=(-max_total_time="$FUZZ_MAX_TIME")
  echo "fuzz: $t, $runs runs ($log)"
  set +e
  "$build/fuzz/$t" "$build/corpus/$t" -runs="$runs" -timeout=1 -rss_limit_mb=2048 \
    -artifact_prefix="$findings/" -print_final_stats=1 "${extra[@]}" >"$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' | tail -1)
  rate=$(grep -E '^stat::average_exec_per_sec' "$log" | awk '{print $2}' | tail -1)
  found=$(find "$findings" -type f | wc -l)
  [ "$rc" -eq 0 ] || status=1
  line="$t: ${execs:-?} executions, ${rate:-?} exec/s, $found finding(s), exit $rc"
  summary+=("$line")
  # The latest run of each target, for docs/RESULTS.md (scripts/report.sh).
  touch "$build/fuzz-summary.txt"
  { grep -v "^$t: " "$build/fuzz-summary.txt" || true; echo "$line ($(date -u +%F))"; } | sort > "$build/fuzz-summary.new"
  mv "$build/fuzz-summary.new" "$build/fuzz-summary.txt"
  echo "fuzz: $line"
  [ "$rc" -eq 0 ] || grep -E 'ERROR|FINDING|SUMMARY|Test unit written' "$log" | head -5 | sed 's/^/  /'
done
printf 'fuzz summary:\n'
printf '  %s\n' "${summary[@]}"
exit "$status"
