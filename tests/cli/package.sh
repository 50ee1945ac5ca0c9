#!/bin/sh
# The C++ package (api/CMakeLists.txt): installed into a temporary prefix,
# the example project outside the tree (examples/cpp) builds against it with
# the shared and with the static library, runs, and writes the lane change's
# telemetry that `bdfcar run` writes, byte for byte.
#   package.sh BUILD_DIR SOURCE_DIR BDFCAR_CLI
set -eu
build=$1 src=$2 cli=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" --component devel > "$tmp/install.log"
for f in include/bdfcar/bdfcar.h lib/libbdfcar.a lib/cmake/bdfcar/bdfcarConfig.cmake share/bdfcar/assets/scenarios/lane_change.toml; do
  [ -e "$tmp/prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
ls "$tmp/prefix"/lib/libbdfcar.so* > /dev/null
"$cli" run "$src/assets/scenarios/lane_change.toml" --duration 2 --out "$tmp/cli.csv" > /dev/null
for variant in shared static; do
  static=OFF
  [ $variant = static ] && static=ON
  cmake -S "$src/examples/cpp" -B "$tmp/ex-$variant" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DBDFCAR_STATIC=$static \
    -DCMAKE_BUILD_TYPE=Release > "$tmp/configure-$variant.log" || { cat "$tmp/configure-$variant.log"; exit 1; }
  cmake --build "$tmp/ex-$variant" -j 2 > "$tmp/build-$variant.log" 2>&1 || { cat "$tmp/build-$variant.log"; exit 1; }
  "$tmp/ex-$variant/lane_change" "$tmp/$variant.csv" > "$tmp/$variant.out" || { cat "$tmp/$variant.out"; exit 1; }
  cat "$tmp/$variant.out"
  cmp "$tmp/cli.csv" "$tmp/$variant.csv" || { echo "FAIL: the $variant example's telemetry differs from bdfcar run's"; exit 1; }
  grep -q "the restored state continues bit for bit" "$tmp/$variant.out" || { echo "FAIL: restore"; exit 1; }
  grep -q "refused: steer must be a finite number" "$tmp/$variant.out" || { echo "FAIL: NaN accepted"; exit 1; }
done
# The shared build found the installed assets, beside the library.
grep -q "assets in $tmp/prefix/share/bdfcar/assets" "$tmp/shared.out" || { echo "FAIL: assets not found installed"; exit 1; }
if grep -q "^frame:" "$tmp/shared.out"; then
  grep -q "^frame: 160x90 .*, [1-9][0-9]* of 43200 bytes lit" "$tmp/shared.out" || { echo "FAIL: frame"; exit 1; }
fi
echo "package: ok"
