// Loading TOML at scale (issue 31: loaders with linear cost): a file of N
// numbers on one line (the shape that was quadratic in toml11: it looked at
// the whole line per value) and the same numbers as rows of 10, parsed by
// the one reader and read as numbers. The time per value should not grow
// with N. Command: build/tests/bench_toml.
#include <benchmark/benchmark.h>

#include <string>

#include "config/range.h"
#include "config/toml_reader.h"

namespace {

std::string numbers(long n, long perLine) {
  std::string s = "a = [";
  for (long i = 0; i < n; ++i) {
    if (i) s += i % perLine == 0 ? ",\n" : ", ";
    s += std::to_string(i % 1000) + ".25";
  }
  return s + "]\n";
}

void load(benchmark::State& state, long perLine) {
  const long n = state.range(0);
  const std::string text = numbers(n, perLine);
  for (auto _ : state) {
    bdfcar::config::Table t = bdfcar::config::parseTomlText(text, "bench.toml");
    benchmark::DoNotOptimize(t.numbers("a", bdfcar::config::Dimension::None, bdfcar::config::Range{}).size());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void BM_TomlOneLine(benchmark::State& state) { load(state, 1L << 40); }
void BM_TomlRowsOf10(benchmark::State& state) { load(state, 10); }

}  // namespace

BENCHMARK(BM_TomlOneLine)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TomlRowsOf10)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
