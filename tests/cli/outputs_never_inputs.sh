#!/bin/sh
# An output never destroys a file the run reads, nor another output:
# --out onto a vehicle part the vehicle file includes is refused and the part
# kept; --out and --metrics naming one file (not there yet) are refused and
# nothing is written. Usage: outputs_never_inputs.sh BDFCAR ASSETS
bdfcar=$1; assets=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
cp -r "$assets/vehicles" "$dir/vehicles"; cp -r "$assets/models" "$dir/models"
part=$dir/vehicles/parts/reference_sedan.toml
"$bdfcar" run "$assets/scenarios/jturn.toml" --vehicle "$dir/vehicles/sedan.toml" --duration 0.1 --out "$part" > "$dir/log" 2>&1
status=$?
cat "$dir/log"
[ "$status" -eq 5 ] || { echo "check: --out onto an included part gave exit $status, expected 5"; exit 1; }
grep -q "this is an input of the run" "$dir/log" || { echo "check: no message naming the input"; exit 1; }
cmp -s "$part" "$assets/vehicles/parts/reference_sedan.toml" || { echo "check: the included part was changed"; exit 1; }
"$bdfcar" run "$assets/scenarios/jturn.toml" --duration 0.1 --out "$dir/same.csv" --metrics "$dir/./same.csv" > "$dir/log" 2>&1
status=$?
cat "$dir/log"
[ "$status" -eq 5 ] || { echo "check: --out equal to --metrics gave exit $status, expected 5"; exit 1; }
grep -q "\-\-out and \-\-metrics name the same file" "$dir/log" || { echo "check: no message naming both"; exit 1; }
[ ! -e "$dir/same.csv" ] || { echo "check: a file was written"; exit 1; }
