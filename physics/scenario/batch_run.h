// A whole scenario run without a window: prepare, step to the end, record
// telemetry at the output interval, stop with a reason on divergence.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <optional>

#include "scenario/course_judge.h"
#include "scenario/simulation.h"
#include "scenario/telemetry.h"

namespace bdfcar::scenario {

struct RunResult {
  bool ok = true;
  std::string failure;              // at which time and which check, when !ok
  double failureTime = 0;
  vehicle::EquilibriumReport equilibrium;
  long steps = 0;                   // manoeuvre steps (settling excluded)
  integ::Counters counters;         // whole run, settling included
  integ::Timers timers;
  double wallSeconds = 0;           // manoeuvre only
  double simulatedSeconds = 0;      // manoeuvre only
  std::vector<vehicle::VehicleSample> samples;  // one per output interval (when kept)
  std::vector<double> steerInputs;  // steering input per sample
  std::optional<CourseResult> course;  // when the scenario has a course
};

struct RunOptions {
  std::string telemetryPath;        // empty: no file
  bool keepSamples = true;
  bool sample = true;               // false: no samples at all (timing the steps alone)
  // Called after each recorded sample (e.g. a course judge).
  std::function<void(const vehicle::VehicleSample&)> onSample;
};

RunResult runScenario(Simulation& sim, const RunOptions& options);

}  // namespace bdfcar::scenario
