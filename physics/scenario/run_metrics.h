// A run's figures as named numbers, for `bdfcar run --metrics` and the
// sweeps' summary (one row per case): what every run has (peaks of the
// responses, the final speed, the course's verdict when there is one), then
// the scenario's standard test (standard_tests.h) when it has one.
#pragma once

#include <string>
#include <vector>

#include "scenario/run.h"

namespace bdfcar::scenario {

struct Metric {
  std::string name;  // lower case with the unit: "peak_ay_mps2"
  double value = 0;  // a verdict is 1 (pass) or 0
};

// From the kept samples (RunOptions::keepSamples); ok = 1 when the run
// ended without a failure.
std::vector<Metric> runMetrics(const RunResult& r);

// One CSV header line and one row (%.10g), or one flat JSON object.
std::string metricsCsv(const std::vector<Metric>& m);
std::string metricsJson(const std::vector<Metric>& m);

}  // namespace bdfcar::scenario
