// The numerical studies behind docs/RESULTS.md: runs of the scenarios with
// chosen integrator settings, compared with the independent reference and
// with the project's own converged runs.
#pragma once

#include <string>
#include <vector>

#include "scenario/batch_run.h"
#include "scenario/scenario_spec.h"

namespace bdfcar::app {

// A column of samples by name (the telemetry's quantities used in comparisons).
std::vector<double> column(const std::vector<vehicle::VehicleSample>& s, const std::string& name);

struct Difference {
  double rmsPercent = 0;  // RMS difference as % of the reference's peak |value|
  double maxAbs = 0;
};
// Compares a run with a reference at the run's sample times (the reference
// interpolated linearly in time): runs at 20 ms have one sample per 20 ms.
Difference compareAt(const std::vector<double>& refTime, const std::vector<double>& reference,
                     const std::vector<double>& runTime, const std::vector<double>& run);

struct RunSummary {
  scenario::RunResult result;
  double wallPerStepUs = 0;  // median over repeats of wall time per manoeuvre step
};

// Runs a scenario `repeats` times (timing only differs) and keeps the last result.
RunSummary runRepeated(const scenario::ScenarioSpec& spec, int repeats);

scenario::ScenarioSpec withIntegrator(scenario::ScenarioSpec s, scenario::IntegratorMethod m, double step, int order,
                                      int newton, int jacobianEvery, bool refresh = true);

// Reference telemetry columns read from a CSV with a header.
std::vector<double> csvColumn(const std::string& path, const std::string& name);

}  // namespace bdfcar::app
