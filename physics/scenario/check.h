// A hard case's check ([check] in its scenario file): the run must finish
// without a divergence, with finite states, the constraint residuals at the
// three levels, the speed and the rise of the centre of mass within their
// bounds, and the named outcome (comes to rest, drives on, stays on four
// wheels, lands and drives on). `bdfcar check` runs them and prints the cost.
#pragma once

#include <string>
#include <vector>

#include "scenario/run.h"

namespace bdfcar::scenario {

struct CheckResult {
  std::string name, file;
  bool passed = true;
  std::vector<std::string> failures;  // each check that did not hold, in words
  std::string outcome;                // what the car did, in words
  StepCost cost;                      // us per step, p50 / p99 / max
  integ::Counters counters;
  double simulated = 0, wall = 0;     // s
  Simulation::ConstraintViolation worst;
  double maxSpeed = 0, maxRise = 0;   // m/s, m
};

// Runs the scenario (with its [check], or the default bounds) and judges it;
// the run's samples go to *samples when given (comparisons with other runs).
// A car that cannot start in the scene (PrepareError) is a failed case whose
// outcome says so; an output that cannot be written still throws.
CheckResult checkScenario(const ScenarioSpec& spec, std::vector<vehicle::VehicleSample>* samples = nullptr);

const char* outcomeName(CheckSpec::Outcome o);

}  // namespace bdfcar::scenario
