#!/usr/bin/env bash
# bdfcar's fidelity rungs side by side with another program's vehicle model,
# timed in one run on this machine (issue 25: the planar rung against the
# 18-DOF model of uwsbel/low-fidelity-dynamic-models, "LFDM"). Fetches and
# builds nothing: give it an LFDM build, or it times bdfcar's rungs alone
# and says so.
#
#   bash scripts/compare-lfdm.sh [--lfdm 'COMMAND' --lfdm-steps N] [--repeats R] [--duration S]
#
#   --lfdm 'COMMAND'  a command line that runs the other model once, e.g. an
#                     LFDM demo built with a 10 ms step and its output off;
#                     run R times, its whole-process wall time divided by
#   --lfdm-steps N    the number of steps that command takes.
#   --repeats R       runs per model (default 5); medians are reported.
#   --duration S      simulated seconds of bdfcar's lane change (default 10).
#
# bdfcar's side: assets/scenarios/lane_change.toml (80 km/h, 10 ms, the
# reference sedan) on each rung, `bdfcar run` with no telemetry; its own
# figure (the run loop: the driver's ticks and the steps, no loading or
# settling) and the whole process's wall time per step (loading, the
# rungs' derivation, `auto`'s certificate and settling included), medians
# over R runs. Whole-process figures of the two programs compare like with
# like; the run loop's is what bdfcar's model costs while it drives. Exit status: 0, or 2 on bad
# arguments, or that of a failed run.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bdfcar=${BDFCAR_BIN:-$root/build/app/bdfcar}
lfdm="" lfdmSteps="" repeats=5 duration=10
usage() { sed -n '2,25p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --lfdm) lfdm=${2:?--lfdm needs a command}; shift 2 ;;
    --lfdm-steps) lfdmSteps=${2:?--lfdm-steps needs a number}; shift 2 ;;
    --repeats) repeats=${2:?--repeats needs a number}; shift 2 ;;
    --duration) duration=${2:?--duration needs seconds}; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare-lfdm.sh: unknown argument '$1' (--help for usage)" >&2; exit 2 ;;
  esac
done
for n in "$repeats" ${lfdmSteps:+"$lfdmSteps"}; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "compare-lfdm.sh: '$n' is not a positive whole number" >&2; exit 2; }
done
if [ -n "$lfdm" ] && [ -z "$lfdmSteps" ]; then
  echo "compare-lfdm.sh: --lfdm needs --lfdm-steps (how many steps the command takes)" >&2
  exit 2
fi
[ -x "$bdfcar" ] || { echo "compare-lfdm.sh: no bdfcar at $bdfcar (build first: bash scripts/build.sh)" >&2; exit 2; }

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
now() { date +%s%N; }

scenario=$root/assets/scenarios/lane_change.toml
steps=$(awk -v d="$duration" 'BEGIN {printf "%d", d / 0.01 + 0.5}')
printf '| model | run loop, us per step | whole process, us per step | real-time factor (run loop) |\n|---|---|---|---|\n'
for rung in linkage kinematic planar auto; do
  alone=() whole=()
  for _ in $(seq "$repeats"); do
    t0=$(now)
    line=$("$bdfcar" run "$scenario" --fidelity "$rung" --duration "$duration" 2>&1 | grep -m1 "us per step")
    t1=$(now)
    alone+=("$(sed -E 's/.*, ([0-9.]+) us per step.*/\1/' <<<"$line")")
    whole+=("$(awk -v a="$t0" -v b="$t1" -v n="$steps" 'BEGIN {print (b - a) / 1000 / n}')")
  done
  a=$(printf '%s\n' "${alone[@]}" | median)
  w=$(printf '%s\n' "${whole[@]}" | median)
  printf '| bdfcar %s | %.2f | %.2f | %.0f |\n' "$rung" "$a" "$w" "$(awk -v a="$a" 'BEGIN {print 1e4 / a}')"
done
if [ -z "$lfdm" ]; then
  echo
  echo "No LFDM build given (--lfdm 'COMMAND' --lfdm-steps N): bdfcar's rungs only."
  exit 0
fi
whole=()
for _ in $(seq "$repeats"); do
  t0=$(now)
  bash -c "$lfdm" >/dev/null
  t1=$(now)
  whole+=("$(awk -v a="$t0" -v b="$t1" -v n="$lfdmSteps" 'BEGIN {print (b - a) / 1000 / n}')")
done
w=$(printf '%s\n' "${whole[@]}" | median)
printf '| %s | - | %.2f | %.0f (whole process) |\n' "$lfdm" "$w" "$(awk -v a="$w" 'BEGIN {print 1e4 / a}')"
