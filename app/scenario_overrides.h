// Command-line options that override a scenario file: the integrator
// settings of the paper's studies, the vehicle, the duration, and any key of
// the scenario or its vehicle (--set KEY=VALUE).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario_spec.h"

namespace bdfcar::app {

struct ScenarioOverrides {
  std::optional<double> step, tick, duration, settle, errorBudget;
  std::optional<std::string> integrator, vehicle, fidelity;
  std::optional<std::string> driver;  // the path-following driver's steering law
  std::optional<int> order, newton, jacobianEvery;
  bool asPublished = false;  // the paper's Newton as published: no refresh when it stops contracting
  std::vector<std::string> settings;  // --set KEY=VALUE, in the order given
};

void addOverrideOptions(CLI::App& cmd, ScenarioOverrides& ov);
// The fidelity ladder's rung names (vehicle/ladder.h), for `--fidelity`.
std::vector<std::string> rungNameList();
// Those and "auto": what `--fidelity` and the pause menu offer.
std::vector<std::string> fidelityChoices();
// A repeatable --set KEY=VALUE option (one setting per occurrence) into `settings`.
void addSetOption(CLI::App& cmd, std::vector<std::string>& settings, const std::string& help);
// Applies the overrides; throws std::runtime_error on a bad combination.
void applyOverrides(const ScenarioOverrides& ov, scenario::ScenarioSpec& spec);
// Loads the scenario file with the --set settings, then applies the other
// overrides; throws config::ConfigError or std::runtime_error.
scenario::ScenarioSpec loadScenario(const std::string& path, const ScenarioOverrides& ov);

}  // namespace bdfcar::app
