// Command-line options that override a scenario file: the integrator
// settings of the paper's studies, the vehicle, the duration.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "scenario/scenario_spec.h"

namespace bdfcar::app {

struct ScenarioOverrides {
  std::optional<double> step, tick, duration, settle, errorBudget;
  std::optional<std::string> integrator, vehicle, fidelity;
  std::optional<int> order, newton, jacobianEvery;
  bool asPublished = false;  // the paper's Newton as published: no refresh when it stops contracting
};

void addOverrideOptions(CLI::App& cmd, ScenarioOverrides& ov);
// Applies the overrides; throws std::runtime_error on a bad combination.
void applyOverrides(const ScenarioOverrides& ov, scenario::ScenarioSpec& spec);

}  // namespace bdfcar::app
