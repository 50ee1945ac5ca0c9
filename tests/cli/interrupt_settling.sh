#!/bin/sh
# A run stopped while the car settles (a settling of 10^4 s, within the
# documented range, would take minutes): SIGINT ends it at once with its
# message and exit 130, and an output of that name is left as it was.
# Usage: interrupt_settling.sh BDFCAR SCENARIO
bdfcar=$1; scenario=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
echo "an earlier file" > "$dir/out.csv"
"$bdfcar" run "$scenario" --settle 10000 --out "$dir/out.csv" > "$dir/log" 2>&1 &
pid=$!
sleep 1
kill -s INT "$pid"
wait "$pid"; status=$?
cat "$dir/log"
[ "$status" -eq 130 ] || { echo "check: SIGINT while settling gave exit $status, expected 130"; exit 1; }
grep -q "stopped by SIGINT before the run began (stopped while settling" "$dir/log" || { echo "check: no message"; exit 1; }
[ "$(cat "$dir/out.csv")" = "an earlier file" ] || { echo "check: the earlier output was changed"; exit 1; }
