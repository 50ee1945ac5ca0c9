#!/bin/sh
# A full disk (here: the file-size limit, ulimit -f, with SIGXFSZ ignored, so
# that write(2) fails with EFBIG as it fails with ENOSPC) loses nothing a
# user had: `run --out` and `render --video` exit 5 naming the file, the
# earlier file of that name is kept as it was, and the telemetry written so
# far is in OUT.partial, ending on a whole row.
# Usage: full_disk_keeps.sh BDFCAR BDFCAR_HEADLESS SCENARIO
bdfcar=$1; headless=$2; scenario=$3
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
echo "an earlier run" > "$dir/out.csv"
( trap '' XFSZ; ulimit -f 64; exec "$bdfcar" run "$scenario" --duration 30 --out "$dir/out.csv" ) > "$dir/run.log" 2>&1
status=$?
cat "$dir/run.log"
[ "$status" -eq 5 ] || { echo "check: run gave exit $status, expected 5"; exit 1; }
grep -q "cannot write" "$dir/run.log" || { echo "check: no 'cannot write' message"; exit 1; }
grep -q "is kept" "$dir/run.log" || { echo "check: the message does not say the earlier file is kept"; exit 1; }
[ "$(cat "$dir/out.csv")" = "an earlier run" ] || { echo "check: the earlier out.csv was changed"; exit 1; }
p=$dir/out.csv.partial
[ -s "$p" ] || { echo "check: no partial telemetry"; exit 1; }
[ "$(tail -c 1 "$p" | od -An -c | tr -d ' ')" = '\n' ] || { echo "check: $p does not end on a whole row"; exit 1; }
awk -F, 'NR == 1 { n = NF } NF != n { print "check: row " NR " has " NF " columns"; bad = 1 } END { exit bad }' "$p" || exit 1
echo "run: exit 5, earlier file kept, $(wc -l < "$p") whole rows in out.csv.partial"

if command -v ffmpeg > /dev/null 2>&1 && [ -x "$headless" ]; then
  echo "an earlier video" > "$dir/v.mp4"
  ( trap '' XFSZ; ulimit -f 8; exec env -u DISPLAY "$headless" render "$scenario" --no-frames --video "$dir/v.mp4" \
      --size 320x180 --fps 30 ) > "$dir/render.log" 2>&1
  status=$?
  tail -n 3 "$dir/render.log"
  [ "$status" -eq 5 ] || { echo "check: render --video gave exit $status, expected 5"; exit 1; }
  [ "$(cat "$dir/v.mp4")" = "an earlier video" ] || { echo "check: the earlier v.mp4 was changed"; exit 1; }
  echo "render --video: exit 5, earlier video kept"
fi
