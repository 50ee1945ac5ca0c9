#!/bin/sh
# Through the program: a recording whose header was removed, an empty one
# and a header-only one are refused (exit 1, file and line named) rather
# than replayed as another drive or as nothing; an output naming a FIFO with
# no reader is refused at once (exit 5) rather than blocking for ever.
# Usage: recordings_and_fifos.sh BDFCAR SCENARIO
bdfcar=$1; scenario=$2
here=$(dirname "$0")
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
check() { sh "$here/check.sh" "$@" || exit 1; }
"$bdfcar" soak --seconds 1 --record "$dir/rec.txt" > /dev/null 2>&1 || { echo "check: soak failed"; exit 1; }
grep -v '^#\|^scenario\|^vehicle\|^tick ' "$dir/rec.txt" > "$dir/bare.txt"
check 1 "bare.txt: it does not name the content of the scenario and vehicle it was recorded with" \
  "$bdfcar" drive --replay "$dir/bare.txt" --batch "$scenario"
: > "$dir/empty.txt"
check 1 "empty.txt:0: no recorded ticks \(an empty recording\)" "$bdfcar" drive --replay "$dir/empty.txt" --batch
grep '^#\|^scenario\|^vehicle\|^tick ' "$dir/rec.txt" > "$dir/header.txt"
check 1 "header.txt:[0-9]+: no recorded ticks" "$bdfcar" drive --replay "$dir/header.txt" --batch
mkfifo "$dir/pipe"
check 5 "pipe: cannot open for writing: a FIFO with no reader" timeout 20 "$bdfcar" run "$scenario" --duration 0.1 --out "$dir/pipe"
echo "recordings and FIFOs: each refused with its reason"
