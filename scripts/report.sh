#!/usr/bin/env bash
# Regenerates docs/RESULTS.md from the code as it is: the physics sections
# (`bdfcar report`), then Google Benchmark medians, headless frame times and
# the interactive loop's statistics. A long study (about 10 minutes), not a
# test: run it on a quiet machine after changes to the physics or the loop.
#
#   BDFCAR_REPEATS        runs / benchmark repetitions per timing (default 5)
#   BDFCAR_DRIVE_SECONDS  wall time of the interactive loop run (default 60;
#                         600 for the issue's 10-minute goal)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BDFCAR_BUILD_DIR:-$root/build}
repeats=${BDFCAR_REPEATS:-5}
drive_seconds=${BDFCAR_DRIVE_SECONDS:-60}
"$root/scripts/build.sh" > /dev/null
cd "$root"
out=docs/RESULTS.md
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$build/app/bdfcar" report --out "$out" --repeats "$repeats"

# The median rows of a Google Benchmark CSV as a Markdown table: name, real
# time, and every user counter (the integrator's split) that the row has.
bench_table() {
  # Console format: the CSV reporter aborts when benchmarks carry different counters.
  "$build/tests/$1" --benchmark_repetitions="$repeats" --benchmark_report_aggregates_only=true \
    --benchmark_color=false 2> /dev/null | awk '
    $1 ~ /_median$/ {
      name = $1; sub(/_median$/, "", name); sub(/\/iterations:[0-9]+/, "", name)
      extra = ""
      for (i = 7; i <= NF; i++) { split($i, kv, "="); extra = extra sprintf(" %s %.2f;", kv[1], kv[2]) }
      printf "| %s | %s %s |%s |\n", name, $2, $3, extra
    }
    /ERROR OCCURRED/ { name = $1; sub(/\/iterations:[0-9]+/, "", name); sub(/.*ERROR OCCURRED: /, ""); printf "| %s | error: %s | |\n", name, $0 }' |
    sort -u
}

{
  echo "## 6. Micro-benchmarks (Google Benchmark, median of $repeats repetitions)"
  echo
  echo "One 10 ms step at the paper's setting (BDF2, at most 2 Newton iterations, Jacobian every 200 steps) through"
  echo "the lane change at 80 km/h, tyres and terrain rays included: Plane = an analytic plane made in"
  echo "code, FlatRoad = flat.toml (an analytic plane read from the file), MeshRoad = curb.toml (a Bullet"
  echo "triangle mesh, one ray per wheel per step)."
  echo "Counters: the integrator's split per step (us). Command: \`build/tests/bench_vehicle\`."
  echo
  echo "| benchmark | real time (median) | split |"
  echo "|---|---|---|"
  bench_table bench_vehicle
  echo
  echo "The multibody core alone on a mechanism of the paper car's size (25 coordinates, 14 constraint"
  echo "equations; \`build/tests/bench_core\`: residual, Jacobian by finite differences + LU, LU alone, one"
  echo "step with its split) and the terrain rays (\`build/tests/bench_terrain\`):"
  echo
  echo "| benchmark | real time (median) | counters |"
  echo "|---|---|---|"
  bench_table bench_core
  bench_table bench_terrain
  echo
  echo "Loading TOML (\`build/tests/bench_toml\`): N numbers on one line, and as rows of 10, parsed and read;"
  echo "the time grows linearly with N (the one-line shape was quadratic in toml11 before the reader split it);"
  echo "items_per_second in thousands of values a second:"
  echo
  echo "| benchmark | real time (median) | counters |"
  echo "|---|---|---|"
  bench_table bench_toml
} >> "$out"

{
  echo "## 6b. Instructions per step (callgrind: steadier than seconds on a shared VM)"
  echo
  if command -v valgrind > /dev/null; then
    echo "J-turn at the paper's setting, no telemetry: instructions of a 6 s run minus those of a 1 s run,"
    echo "over the 500 steps between. Command: \`valgrind --tool=callgrind build/app/bdfcar run"
    echo "assets/scenarios/jturn.toml --vehicle assets/vehicles/paper.toml --duration 6\` (and 1)."
    echo
    echo "Beside each: its share of the same vehicle's linkage (one run each, same binary), the target"
    echo "of issue 25 where it sets one, and the real-time factor \`bdfcar run\` prints (no telemetry;"
    echo "median of 5 runs of the 4 s J-turn, wall time: this machine's, not steady)."
    echo
    echo "| vehicle | instructions per 10 ms step | of the linkage's | target | real-time factor |"
    echo "|---|---|---|---|---|"
    # The vehicle file, then the models derived from it (section 5b): what a
    # scene that does not need the linkage saves per step; `auto` includes its
    # scan of the road ahead and its switches.
    declare -A linkageIr
    for run in "paper linkage <=70000" "sedan linkage <=100000" "sedan linkage - fidelity.newton_stops_within_tolerance=false" \
               "paper kinematic -" "sedan kinematic <=25000" \
               "sedan kinematic -  fidelity.kinematic_equations=multibody" "sedan kinematic - fidelity.newton_stops_within_tolerance=false" \
               "sedan planar <=6000" "sedan planar -  fidelity.planar_equations=multibody" \
               "sedan planar - fidelity.newton_stops_within_tolerance=false" "sedan auto -"; do
      set -- $run
      v=$1 f=$2 target=$3 extra=() tag=""
      [ -n "${4:-}" ] && extra=(--set "$4") && tag=".${4//[^a-z0-9]/_}"
      # (the run's tag named outside ir(): inside it $4 is ir's own, empty,
      # and every variant's profile overwrote the default run's)
      ir() {
        valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.$v.$f$tag.$1" "$build/app/bdfcar" run \
          assets/scenarios/jturn.toml --vehicle "assets/vehicles/$v.toml" --fidelity "$f" "${extra[@]}" --duration "$1" 2>&1 |
          awk '/Collected/ { print $4 }'
      }
      rtf() {
        for _ in 1 2 3 4 5; do
          "$build/app/bdfcar" run assets/scenarios/jturn.toml --vehicle "assets/vehicles/$v.toml" --fidelity "$f" "${extra[@]}" 2>&1 |
            sed -nE 's/.*real-time factor ([0-9]+).*/\1/p'
        done | sort -n | sed -n 3p
      }
      label="$v.toml"
      [ "$f" != linkage ] && label="$v.toml, \`--fidelity $f\`"
      case "${4:-}" in
        *_equations=multibody) label="$label, the same equations in the multibody form (\`--set $4\`)" ;;
        fidelity.newton_stops_within_tolerance=*) label="$label, the paper's two Newton iterations in full (\`--set $4\`; the default ends at the first within tolerance)" ;;
      esac
      perStep=$(( ($(ir 6) - $(ir 1)) / 500 ))
      [ "$f" = linkage ] && [ -z "${4:-}" ] && linkageIr[$v]=$perStep  # the default run is the reference
      share=$(awk -v a="$perStep" -v b="${linkageIr[$v]}" 'BEGIN { printf "%.2f", a / b }')
      echo "| $label | $perStep | $share | $target | $(rtf) |"
    done
    # Telemetry at every step (a CSV row of 52 columns per 10 ms step): the
    # stepping thread pays for the sample, the writer thread formats the row;
    # each thread's instructions (callgrind --separate-threads: -01 is the
    # main thread, -02 the writer).
    irOut() {
      valgrind --tool=callgrind --separate-threads=yes --callgrind-out-file="$tmp/cg.out.$1" "$build/app/bdfcar" run \
        assets/scenarios/jturn.toml --vehicle assets/vehicles/paper.toml --duration "$1" --out "$tmp/out.$1.csv" \
        > /dev/null 2>&1
      for thread in 01 02; do
        callgrind_annotate "$tmp/cg.out.$1-$thread" 2> /dev/null | awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1 }'
      done
    }
    read -r main6 writer6 <<< "$(irOut 6 | xargs)"
    read -r main1 writer1 <<< "$(irOut 1 | xargs)"
    echo "| paper.toml with \`--out\` (a telemetry row every step): the stepping thread | $(( (main6 - main1) / 500 )) | | | |"
    echo "| ... and the telemetry writer's thread (formatting the row) | $(( (writer6 - writer1) / 500 )) | | | |"
    echo
    # The proving-ground lap (issue 25's `auto` target, 5g's wall-time ratio)
    # in instructions: a whole driver's tick (the path follower, the rung's
    # policy and its scan of the road ahead, the step), 176 s less 1 s (the
    # start-up, and under `auto` the ladder certificate's runs, alike in both).
    lapIr() {  # lapIr FIDELITY DURATION
      valgrind --tool=callgrind --collect-atstart=no "--toggle-collect=bdfcar::scenario::Run::tick(*" \
        --callgrind-out-file="$tmp/cg.lap.$1.$2" "$build/app/bdfcar" run \
        assets/scenarios/proving_ground/circuit_lap.toml --fidelity "$1" --duration "$2" 2>&1 |
        awk '/Collected/ { print $4 }'
    }
    lapTick() {
      local short long
      short=$(lapIr "$1" 1)  # first: it also fills the derivation cache the long run reads
      long=$(lapIr "$1" 176)
      echo $(( (long - short) / 17500 ))
    }
    lapAuto=$(lapTick auto) lapLinkage=$(lapTick linkage)
    echo "The proving-ground lap (circuit_lap.toml, the first 176 s less the first 1 s: 17,500 ticks of the"
    echo "driver, each its path follower, the rung's policy with its scan of the road ahead, and the step;"
    echo "\`--toggle-collect\` on Run::tick): \`--fidelity auto\` $lapAuto instructions per tick, the linkage"
    echo "$lapLinkage, ratio $(awk -v a="$lapAuto" -v b="$lapLinkage" 'BEGIN { printf "%.3f", a / b }') (issue 25's target for the"
    echo "lap's wall-time ratio, section 5g: 0.25)."
    echo
    echo "Where a step's instructions go (paper.toml; inclusive, % of all instructions inside"
    echo "BdfIntegrator::step over the run, settling included; \`--toggle-collect\` on that function):"
    echo
    valgrind --tool=callgrind --collect-atstart=no "--toggle-collect=bdfcar::integ::BdfIntegrator::step(*" \
      --callgrind-out-file="$tmp/cg.step" "$build/app/bdfcar" run assets/scenarios/jturn.toml \
      --vehicle assets/vehicles/paper.toml --duration 6 > /dev/null 2>&1
    echo "| function | share of the step |"
    echo "|---|---|"
    callgrind_annotate --auto=no --inclusive=yes "$tmp/cg.step" 2> /dev/null |
      sed -nE 's/^ *[0-9,]+ \( *([0-9.]+%)\) *[^:]*:([^(<]*)[(<].*/\2 \1/p' | awk '!seen[$1]++' |
      grep -E '::(newton|residual|applyForces|VehicleForces::apply|FialaTyre::evaluate|applySprings|updatePositions|updateVelocities|updateAccelerations|inverseDynamics|constraintResiduals|applyConstraintWrenches|general_matrix_vector_product|evaluateJacobian|MultibodyDae::retract) ' |
      awk '{ printf "| %s | %s |\n", $1, $2 }'
    echo
    echo "general_matrix_vector_product is the back-substitution: products with the stored inverse of"
    echo "the eq. 3.8 matrix and with the Jacobian blocks; evaluateJacobian (finite differences of the"
    echo "residual, every 200 steps) is amortised; the rest of newton is the residual."
    echo
    # Self instructions by function: its qualified name without its return
    # type and template arguments, but for a residual's two instances (T
    # double: the residual; T ad::Dual, marked [dual]: its Jacobian).
    selfIr() {
      callgrind_annotate --auto=no --threshold=100 "$1" 2> /dev/null | sed 's/(anonymous namespace)/{anonymous}/g' |
        sed -nE 's/^ *([0-9,]+) +\([ 0-9.%]+\) +[^:]*:(.*)/\1 \2/p' | tr -d ',' |
        awk '{ n = $1; name = substr($0, length($1) + 2); cut = index(name, "("); if (cut) name = substr(name, 1, cut - 1)
               gsub(/<bdfcar::ad::Dual>/, "[dual]", name); while (gsub(/<[^<>]*>/, "", name)) {}
               k = split(name, part, " "); a[part[k]] += n }
             END { for (f in a) print f, a[f] }'
    }
    # A closed-form rung's self instructions per step, the functions above 2 %.
    profileTable() {
      echo "| function | instructions per step | share |"
      echo "|---|---|---|"
      join <(selfIr "$tmp/cg.sedan.$1.6" | sort) <(selfIr "$tmp/cg.sedan.$1.1" | sort) |
        awk '{ d = ($2 - $3) / 500; tot += d; row[$1] = d } END { for (k in row) if (row[k] > 0.02 * tot) printf "%d %s %.1f\n", row[k], k, 100 * row[k] / tot }' |
        sort -rn | awk '{ printf "| %s | %d | %s %% |\n", $2, $1, $3 }'
    }
    echo "Where the planar rung's step goes (sedan.toml \`--fidelity planar\`; self instructions per step"
    echo "over the 500 steps between the 1 s and the 6 s run, the functions above 2 %): the closed form's"
    echo "equations (PlanarCar::equations: about 1.05 residuals a step, Newton ending at the first iteration"
    echo "within tolerance, or whose iterate is by Newton's contraction; their [dual] instance, the exact"
    echo "Jacobian, taken once here: Newton never found it stale), the"
    echo "tyres, the BDF step's own work (substep, newton, the kernels of bdf_kernels.h) and the step's"
    echo "acceptance (each wheel's ground for the next step, its slip state). No function holds a quarter"
    echo "of the step: the 6k target asks for every part halved, not one removed."
    echo
    profileTable planar
    echo
    echo "Where the kinematic rung's step goes (sedan.toml \`--fidelity kinematic\`, its closed form,"
    echo "physics/vehicle/kinematic_car.h; the same measure): the corners' tables (SplineGrid::eval: the"
    echo "steered corners' are bicubic in travel and rack, six pose components and the springs' lengths"
    echo "with their first and second derivatives; each corner's cell kept as cubics in the travel, contracted"
    echo "along the rack once a step), the corners' motion from them (cornerMotion) and the residual's own"
    echo "algebra, for each of the step's residuals (about one: Newton ends at the first iteration within"
    echo "tolerance, or whose iterate is by Newton's contraction)."
    echo
    profileTable kinematic
    echo
    # Issue 26's cost target (rough road <= 1.5x flat) is missed: where the
    # relief's extra instructions go, the same case on its own relief and on
    # flat.toml (the same enveloping tyres, driver, steps and policy), 5 s
    # less 2 s (the 300 steps of the lane change and after; the settling and
    # start-up alike in both cancel).
    roughRun() {  # roughRun TERRAIN DURATION: instructions (and the run's line kept)
      valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.rough.$1.$2" "$build/app/bdfcar" run \
        assets/scenarios/hard/rough_lane_change.toml --set "scenario.terrain=assets/terrain/$1.toml" --duration "$2" \
        > "$tmp/rough.$1.$2.txt" 2>&1
      awk '/Collected/ { print $4 }' "$tmp/rough.$1.$2.txt"
    }
    newtonOf() { sed -nE 's/.* ([0-9]+) Newton iterations.*/\1/p' "$tmp/rough.$1.$2.txt" | tail -n 1; }
    declare -A roughIr roughIt
    for t in rough flat; do
      roughIr[$t]=$(( ($(roughRun "$t" 5) - $(roughRun "$t" 2)) / 300 ))
      roughIt[$t]=$(awk -v a="$(newtonOf "$t" 5)" -v b="$(newtonOf "$t" 2)" 'BEGIN { printf "%.2f", (a - b) / 300 }')
    done
    echo "Where the rough road's step goes (hard/rough_lane_change.toml, the linkage on enveloping tyres,"
    echo "against the same case on flat.toml: \`--set scenario.terrain=assets/terrain/flat.toml\`; the 300"
    echo "steps between a 2 s and a 5 s run): ${roughIr[rough]} instructions a step on the relief, ${roughIr[flat]}"
    echo "on flat ($(awk -v a="${roughIr[rough]}" -v b="${roughIr[flat]}" 'BEGIN { printf "%.2f", a / b }')x; issue 26's target 1.5x), with ${roughIt[rough]} and ${roughIt[flat]} Newton iterations"
    echo "a step (residuals of the step's pieces: a step on the relief goes in about two pieces, each"
    echo "judged by its predictor's miss), so $(awk -v a="${roughIr[rough]}" -v b="${roughIt[rough]}" 'BEGIN { printf "%.0f", a / b }') and $(awk -v a="${roughIr[flat]}" -v b="${roughIt[flat]}" 'BEGIN { printf "%.0f", a / b }') instructions an iteration. Self"
    echo "instructions per step by function, those above 2 % of either (the envelope's: the lattice's"
    echo "heights, the cams' search, the profile's sampling; the multibody residual's recursive passes;"
    echo "the back-substitution's products):"
    echo
    echo "| function | on the relief | on flat |"
    echo "|---|---|---|"
    join -a 1 -e 0 -o 0,1.2,2.2 <(join <(selfIr "$tmp/cg.rough.rough.5" | sort) <(selfIr "$tmp/cg.rough.rough.2" | sort) |
                                   awk '{ print $1, int(($2 - $3) / 300) }' | sort) \
                                 <(join <(selfIr "$tmp/cg.rough.flat.5" | sort) <(selfIr "$tmp/cg.rough.flat.2" | sort) |
                                   awk '{ print $1, int(($2 - $3) / 300) }' | sort) |
      awk -v R="${roughIr[rough]}" -v F="${roughIr[flat]}" '$2 > 0.02 * R || $3 > 0.02 * F { print }' |
      sort -k2,2nr | awk '{ printf "| %s | %d | %d |\n", $1, $2, $3 }'
    echo
    awk -v R="${roughIr[rough]}" -v F="${roughIr[flat]}" -v iR="${roughIt[rough]}" -v iF="${roughIt[flat]}" 'BEGIN {
      extra = R - F; iterations = (iR - iF) * F / iF
      printf "Of the %d extra instructions a step, the extra iterations at flat ground'"'"'s cost per iteration\n", extra
      printf "account for %d (%.0f %%); the rest, %d, is what an iteration on the relief costs more (the\n", iterations, 100 * iterations / extra, extra - iterations
      printf "envelope'"'"'s lattice and cams above, and the pieces'"'"' own factorizations and acceptances).\n" }'
    echo
    # Where those iterations come from: the case with one thing of the
    # policy or the road changed at a time (scripts/relief_study.sh).
    echo "Where the relief's Newton iterations come from (\`bash scripts/relief_study.sh [SCENARIO] [T1] [T2]\`):"
    echo "the case with the default policy and with one thing changed at a time, its Newton iterations per"
    echo "10 ms over the window (a run to T2 less one to T1), its stalled steps (refreshed / rescued) and"
    echo "refined ones, and its distance to the same case converged at 1 ms on the same road (the measure"
    echo "of 5d). What to read in it: whether a fresh Jacobian or the ground held through the step buys"
    echo "iterations (the Jacobian's age, the road followed inside Newton); what the refinement costs"
    echo "against whole steps and against a fixed 5 ms step, and what it buys in distance; how the"
    echo "iterations go with the road's amplitude, down to flat ground."
    echo
    bash "$root/scripts/relief_study.sh" "$root/assets/scenarios/hard/rough_lane_change.toml" 2 5 2> /dev/null
    echo
    bash "$root/scripts/relief_study.sh" "$root/assets/scenarios/hard/washboard_60.toml" 2 5 2> /dev/null
    echo
    echo "The planar rung beside LFDM's 18-DOF model (a two-track model with roll, TMeasy tyres,"
    echo "half-implicit; uwsbel/low-fidelity-dynamic-models), a lane change at 80 km/h with a 10 ms step,"
    echo "in one run on this machine: \`bash scripts/lfdm_side_by_side.sh LFDM_SOURCE_DIR\` (LFDM_DIR for the"
    echo "report; it compiles LFDM from a tree you give it and fetches nothing):"
    echo
    bash "$root/scripts/lfdm_side_by_side.sh" "${LFDM_DIR:-}" 2>&1 | sed 's/^/    /'
  else
    echo "(skipped: valgrind is not installed)"
  fi
  echo
} >> "$out"

{
  echo "## 7. Headless rendering (OSMesa, no display server)"
  echo
  echo "The ISO 3888-1 lane change at 1280x720, 30 frames per simulated second, chase camera; rendering"
  echo "on the main thread, encoding beside it at a lower priority (render/thread_priority.h): PNG on a"
  echo "worker thread, or the video's ffmpeg (x264 ultrafast). Render is the draw of one frame; end to end"
  echo "is the whole run's wall time per frame, encoding paid for (on 2 cores the encoder bounds it)."
  echo "Commands: \`env -u DISPLAY build/app/bdfcar render assets/scenarios/iso_lane_change.toml --out frames\`"
  echo "(PNG frames), then the same with \`--no-frames --video run.mp4\` (video only)."
  echo
  echo "$repeats runs of each; the line printed is each run's, the medians over the runs below them."
  echo
  echo '```'
  render_runs() {  # render_runs LABEL ARGS...: one line per run, then the medians
    local label=$1 line runs=()
    shift
    for ((r = 0; r < repeats; ++r)); do
      rm -rf "$tmp/frames"
      line=$(env -u DISPLAY -u WAYLAND_DISPLAY "$build/app/bdfcar-headless" render \
        assets/scenarios/iso_lane_change.toml --size 1280x720 "$@" 2>&1 | tail -n 1)
      echo "$line"
      runs+=("$line")
    done
    printf '%s\n' "${runs[@]}" | awk -v label="$label" '
      { for (i = 1; i <= NF; ++i) {
          if ($i == "p50" && $(i - 1) == "render") r[NR] = $(i + 1)
          if ($i == "frame" && $(i + 1) == "end") e[NR] = $(i - 3) } }
      function median(a, n,   i, j, t) {
        for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
        return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
      END { printf "%s, median of %d runs: render p50 %.1f ms, %.1f ms a frame end to end\n", label, NR, median(r, NR), median(e, NR) }'
  }
  render_runs "PNG frames" --out "$tmp/frames"
  if command -v ffmpeg > /dev/null; then
    render_runs "video only" --no-frames --video "$tmp/run.mp4"
  fi
  echo '```'
  echo
  # Instructions are steadier than milliseconds on a shared machine: the
  # rasteriser's threads are counted too (callgrind serialises them).
  if command -v valgrind > /dev/null && [ -x "$build/tests/bench_render" ]; then
    echo "Instructions per frame, all threads (the synthetic lane change, 10 frames after 5 warm-up, no PNG):"
    echo "\`valgrind --tool=callgrind --instr-atstart=no build/tests/bench_render 10 1280 720 -1\`."
    echo
    echo '```'
    (env -u DISPLAY -u WAYLAND_DISPLAY valgrind --tool=callgrind --instr-atstart=no \
      --callgrind-out-file="$tmp/cg.render" "$build/tests/bench_render" 10 1280 720 -1 2>&1 |
      awk '/Collected/ { printf "render: %.1f M instructions per frame\n", $4 / 10 / 1e6 }')
    echo '```'
    echo
  fi
} >> "$out"

{
  echo "### 7b. Frames on the proving ground, by area"
  echo
  echo "Each of drive_powertrain.toml's [[places]] with the car standing there, and the circuit driven"
  echo "(circuit_lap.toml, its first 40 s): chase camera, 1280x720, HUD and track map on, frames drawn and"
  echo "not written (no encoder competing for the 2 cores), software GL (OSMesa, llvmpipe). Commands:"
  echo "\`env -u DISPLAY build/app/bdfcar render assets/scenarios/drive_powertrain.toml --place N --no-frames"
  echo "--duration 2\` and \`... render assets/scenarios/proving_ground/circuit_lap.toml --no-frames --duration 40\`."
  echo "Medians over $repeats runs of each run's render p50 and p99; frames per second = 1000 / p50; what a"
  echo "frame draws (the median frame's triangles and drawables after culling and level of detail): a"
  echo "count, the same on any machine, where the milliseconds move with the machine's load."
  echo
  echo "| area | render p50 | render p99 | frames per second at p50 | triangles / drawables a frame |"
  echo "|---|---|---|---|---|"
  frame_row() {  # frame_row LABEL ARGS...: one table row from $repeats runs
    local label=$1 r lines=()
    shift
    for ((r = 0; r < repeats; ++r)); do
      lines+=("$(env -u DISPLAY -u WAYLAND_DISPLAY "$build/app/bdfcar-headless" render "$@" --size 1280x720 --no-frames 2>&1 |
        grep ' frames .*render p50' | tail -n 1)")
    done
    printf '%s\n' "${lines[@]}" | awk -v label="$label" '
      { for (i = 1; i <= NF; ++i) {
          if ($i == "p50" && $(i - 1) == "render") a[NR] = $(i + 1)
          if ($i == "p99" && $(i - 3) == "p50") b[NR] = $(i + 1)
          if ($i == "p50" && $(i - 1) == "drawn") { t[NR] = $(i + 1); d[NR] = $(i + 4) } } }
      function median(x, n,   i, j, t) {
        for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
        return n % 2 ? x[(n + 1) / 2] : (x[n / 2] + x[n / 2 + 1]) / 2 }
      END { p50 = median(a, NR); p99 = median(b, NR)
            printf "| %s | %.1f ms | %.1f ms | %.0f | %.0f / %.0f |\n", label, p50, p99, (p50 > 0 ? 1000 / p50 : 0),
                   median(t, NR), median(d, NR) }'
  }
  place=0 rough=0
  while IFS= read -r name; do
    place=$((place + 1))
    [ "$name" = "rough road" ] && rough=$place
    frame_row "$name (place $place)" assets/scenarios/drive_powertrain.toml --place "$place" --duration 2
  done < <(sed -n 's/^name = "\(.*\)"$/\1/p' <(sed -n '/^\[\[places\]\]/,$p' assets/scenarios/drive_powertrain.toml))
  # The rough road's place is its flat run-in; also 100 m on, on the relief
  # (the proving ground's rough section lies along y = -160 m, right lane).
  if [ "$rough" -gt 0 ]; then
    frame_row "rough road, on its relief (100 m in)" assets/scenarios/drive_powertrain.toml --place "$rough" \
      --set "places[$((rough - 1))].position=[100.0, -161.75]" --duration 2
  fi
  frame_row "the circuit, driven (first 40 s)" assets/scenarios/proving_ground/circuit_lap.toml --duration 40
  echo
} >> "$out"

{
  echo "## 8. The interactive loop"
  echo
  echo "\`bdfcar drive\` with paper.toml at the paper's setting, keyboard idle (the car rolls on), for"
  echo "$drive_seconds s of wall time; tick period, physics per tick, render per frame, peak resident memory."
  echo "Command: \`build/app/bdfcar drive --vehicle assets/vehicles/paper.toml --seconds $drive_seconds\`"
  echo "(under \`xvfb-run -a -s '-screen 0 1280x720x24'\` when there is no display: software GL, no"
  echo "multisampling (\`--msaa\`: none on software GL unless asked), the sound through SDL's dummy audio driver)."
  echo "The default scene: the proving ground (drive_powertrain.toml), sound, lap timing and the pause menu on;"
  echo "Mesa's rasteriser with a thread a core, below the tick's priority; the world at full resolution"
  echo "(\`--render-scale auto\`: on software GL stretching a smaller picture costs what it saves)."
  echo
  # The drive, or a line saying why there is none.
  drive() {
    local cmd=("$build/app/bdfcar" drive --vehicle assets/vehicles/paper.toml --size 1280x720 "$@")
    if [ -n "${DISPLAY:-}" ]; then
      "${cmd[@]}" 2>&1 | grep -A4 '^loop:' || echo "(the drive did not report loop statistics)"
    elif command -v xvfb-run > /dev/null; then
      # No sound card there either: SDL's dummy audio driver pulls the sound at
      # the real rate, so the synthesiser runs as it would on a desktop.
      SDL_AUDIODRIVER=${SDL_AUDIODRIVER:-dummy} xvfb-run -a -s '-screen 0 1280x720x24' "${cmd[@]}" 2>&1 |
        grep -A4 '^loop:' || echo "(the drive did not report loop statistics)"
    else
      echo "(skipped: no display and no xvfb-run)"
    fi
  }
  echo '```'
  drive --seconds "$drive_seconds"
  echo '```'
  echo
  echo "The same drive for $((drive_seconds / 2)) s, then again with one rasteriser thread (\`LP_NUM_THREADS=1\`, the"
  echo "loop's setting until issue 30's frame-rate work), one after the other on the same machine: frames"
  echo "against the tick's jitter."
  echo
  echo '```'
  drive --seconds "$((drive_seconds / 2))" | sed -n 1,2p
  LP_NUM_THREADS=1 drive --seconds "$((drive_seconds / 2))" | sed -n 1,2p
  echo '```'
  echo
  echo "The car's sound (audio/, issue 30) is rendered on SDL's audio thread, not the tick: the tick only"
  echo "publishes a SoundState through a triple buffer. One tick's worth (480 samples at 48 kHz) of the"
  echo "synthesiser, and the publish (\`build/tests/bench_audio\`, median of $repeats repetitions):"
  echo
  echo "| benchmark | real time (median) | |"
  echo "|---|---|---|"
  bench_table bench_audio
  echo
} >> "$out"

{
  echo "## 9. Hard cases in files (\`bdfcar check\`)"
  echo
  echo "assets/scenarios/hard/: each scenario states what must hold in its [check] table (no divergence,"
  echo "finite states, constraint residuals at the three levels, speed and rise bounds, an outcome)."
  echo "The default Newton policy at 10, 20 and 40 ms (tick = step where the step is longer than 10 ms);"
  echo "wall time per step p50 / p99 / max in us (one run, this machine) and the steps the policy"
  echo "refreshed, rescued (full Newton) or split. Command: \`build/app/bdfcar check [--step H --tick H]\`."
  for h in 0.01 0.02 0.04; do
    echo
    echo "**h = $(awk -v h="$h" 'BEGIN { print h * 1000 }') ms**"
    echo
    if [ "$h" = 0.01 ]; then args=(); else args=(--step "$h" --tick "$h"); fi
    "$build/app/bdfcar" check "${args[@]}" 2> /dev/null | grep -E '^\||passed|: ' || true
  done
  echo
} >> "$out"

{
  echo "## 10. Sanitizers and fuzzing"
  echo
  echo "The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (\`bash scripts/sanitize.sh\`,"
  echo "its own build folder) and libFuzzer over the file loaders (\`bash scripts/fuzz.sh\`); both are long"
  echo "studies, not part of CI. The latest sanitizer run on this machine (its summary, if it was run):"
  echo
  echo '```'
  cat "$root/build-asan/sanitize-summary.txt" 2> /dev/null || echo "(not run on this machine: bash scripts/sanitize.sh)"
  echo '```'
  echo
  echo "The latest libFuzzer run of each target on this machine (1 s timeouts, ASan + UBSan; findings and"
  echo "their fixes in docs/sanitizers-and-fuzzing.md):"
  echo
  echo '```'
  cat "$root/build-fuzz/fuzz-summary.txt" 2> /dev/null || echo "(not run on this machine: bash scripts/fuzz.sh)"
  echo '```'
  echo
} >> "$out"

{
  echo "## 11. Soak: an hour of driving"
  echo
  echo "One simulated hour on the flat road with seeded, bounded random inputs, and one with the steering"
  echo "flipped full left / full right every tick at up to 80 km/h, replayed as \`drive --replay --batch\`"
  echo "replays a recording (\`bdfcar soak\` writes the recording; replaying it gives the same telemetry):"
  echo "divergences, non-finite samples, the largest constraint residual at the three levels (sampled once"
  echo "a simulated second), resident memory. Command: \`bash scripts/soak.sh\` (or \`build/app/bdfcar soak"
  echo "--kind random|flipflop --seconds 3600\`)."
  echo
  echo '```'
  BDFCAR_BUILD_DIR="$build" bash "$root/scripts/soak.sh" "$tmp" 2>&1 | grep -E '^(soak|constraint|resident)'
  echo '```'
  echo
} >> "$out"

# The Python module's timings (issue 29's targets), when it is built.
if [ -d "$build/python/bdfcar" ]; then
  py=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build/CMakeCache.txt")
  { PYTHONPATH="$build/python" "${py:-python3}" "$root/python/bench/bench_python.py" "$repeats"; echo; } >> "$out"
fi
echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), shared VM." >> "$out"
echo "wrote $out"
