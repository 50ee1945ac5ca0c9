#!/bin/sh
# Line-oriented inputs (OBJ meshes, CSV tables, input recordings) are read
# under config::LineReader's limits, generated here at their edges and run
# through the program: a line over 64 KiB (4 KiB in a recording) is refused
# at its line, a file over the size cap before it is read, an OBJ that fans
# into more than 4 million triangles at the line that passes the cap; a
# device is refused by name. Each: exit 1 and the file, line and limit named.
# Usage: line_limits.sh BDFCAR ASSETS
bdfcar=$1; assets=$2
here=$(dirname "$0")
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
check() { sh "$here/check.sh" "$@" || exit 1; }
long_line() { head -c "$1" /dev/zero | tr '\0' "$2"; echo; }

# OBJ: one 70,000-byte line, a 17 MiB file, 4,000,001 triangles from fans.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' > "$dir/long.obj"
{ printf 'f'; long_line 70000 ' '; } >> "$dir/long.obj"
printf 'kind = "mesh"\nfriction = 0.8\n[mesh]\nobj = "long.obj"\n' > "$dir/long.toml"
check 1 "long.obj:4: this line of the OBJ file is longer than 64 KiB, its limit for one line" \
  "$bdfcar" info "$dir/long.toml"
truncate -s 17M "$dir/big.obj"
sed 's/long.obj/big.obj/' "$dir/long.toml" > "$dir/big.toml"
check 1 "big.obj:0: the OBJ file is 17825792 bytes, over its limit of 16 MiB" "$bdfcar" info "$dir/big.toml"
# 32,000 corners a line (64,000 bytes) fan into 31,998 triangles: the 126th face line (line 129) passes 4,000,000.
{ printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n'
  awk 'BEGIN { s = "f"; for (i = 0; i < 16000; ++i) s = s " 1 2"; for (l = 0; l < 130; ++l) print s }'; } > "$dir/fans.obj"
sed 's/long.obj/fans.obj/' "$dir/long.toml" > "$dir/fans.toml"
check 1 "fans.obj:129: more than 4000000 triangles \(the limit for an OBJ file\)" "$bdfcar" info "$dir/fans.toml"

# CSV steering table: a 70,000-byte row.
{ echo "time_s,steer"; echo "0,0"; long_line 70000 '1'; } > "$dir/steer.csv"
cat > "$dir/csv.toml" <<TOML
include = "$assets/../tests/data/bad/parts/mini_scenario.toml"
[steering]
type = "csv"
file = "steer.csv"
column = "steer"
TOML
check 1 "steer.csv:3: this line of the CSV file is longer than 64 KiB" "$bdfcar" run "$dir/csv.toml" --duration 0.1

# Input recording: a 5,000-byte line, and a device.
"$bdfcar" soak --seconds 1 --record "$dir/rec.txt" > /dev/null 2>&1 || { echo "check: soak failed"; exit 1; }
long_line 5000 '0' >> "$dir/rec.txt"
check 1 "rec.txt:[0-9]+: this line of the input recording is longer than 4 KiB" "$bdfcar" drive --replay "$dir/rec.txt" --batch
check 1 "/dev/zero:0: the input recording is a device, not a regular file" "$bdfcar" drive --replay /dev/zero --batch
echo "line limits: every case refused with its file, line and limit"
