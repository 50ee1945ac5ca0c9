// A sweep file (SWEEP.toml, docs/SWEEPS.md): which tests (scenario files),
// which keys to vary over a grid or a seeded Monte Carlo draw, and what to
// plot. A case is one test with one setting of the varied keys: one
// `bdfcar run` command line (sweep_jobs.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/toml_reader.h"

namespace bdfcar::app {

struct SweepVariable {
  std::vector<std::string> keys;    // set together to the same value (e.g. start.speed and the speed hold's target)
  std::string label;                // the column name in the summary: the first key
  // Grid: the values, as TOML text.
  std::vector<std::string> values;
  // Monte Carlo: uniform in [min, max] or normal (mean, sd), with a unit
  // appended to the drawn number ("km/h"; empty: SI).
  enum class Distribution { Uniform, Normal } distribution = Distribution::Uniform;
  double min = 0, max = 0, mean = 0, sd = 0;
  std::string unit;
};

struct SweepSpec {
  std::string name, sourceFile;
  std::vector<std::string> tests;          // scenario files (resolved)
  std::vector<config::Setting> fixed;      // settings of every case (set = [...])
  std::vector<SweepVariable> vary;
  bool monteCarlo = false;
  int samples = 0;                         // Monte Carlo draws per test
  std::uint64_t seed = 1;
  // What the summary plots show: a metric against the first variable, one
  // curve per value of the second (a carpet), and a telemetry channel over
  // time for every case (an overlay).
  std::string plotMetric, plotChannel = "yawrate_radps";
};

struct SweepCase {
  std::string id;                          // "case_0007"
  std::string test;                        // scenario file
  std::vector<std::string> values;         // one per variable, as written (the summary's columns)
  std::vector<config::Setting> settings;   // fixed, then the varied keys
};

// A TOML basic string of s (quotes and backslashes escaped).
std::string tomlQuoted(const std::string& s);

// Throws config::ConfigError naming the file, line and key.
SweepSpec loadSweepFile(const std::string& path);

// Every case, in order: tests outermost, then the variables' values with the
// last varying fastest (a grid), or `samples` draws per test (Monte Carlo,
// the same for the same seed).
std::vector<SweepCase> sweepCases(const SweepSpec& spec);

}  // namespace bdfcar::app
