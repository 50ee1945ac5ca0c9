#include "scenario_overrides.h"

#include "vehicle/ladder.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace bdfcar::app {

std::vector<std::string> rungNameList() {
  std::vector<std::string> names;
  for (const vehicle::RungDescription& r : vehicle::ladder()) names.push_back(r.name);
  return names;
}

std::vector<std::string> fidelityChoices() {
  std::vector<std::string> names = rungNameList();
  names.push_back("auto");
  return names;
}

void addOverrideOptions(CLI::App& cmd, ScenarioOverrides& ov) {
  cmd.add_option("--step", ov.step, "Integration step, s")->check(CLI::Range(1e-6, 0.1));
  cmd.add_option("--tick", ov.tick, "The driver's input period, s (default: the scenario's, 10 ms); a whole number of steps")
      ->check(CLI::Range(1e-3, 0.1));
  cmd.add_option("--integrator", ov.integrator, "bdf, rk4 or euler")->check(CLI::IsMember({"bdf", "rk4", "euler"}));
  cmd.add_option("--order", ov.order, "BDF order")->check(CLI::Range(1, 5));
  cmd.add_option("--newton", ov.newton, "Newton iterations per step (0 = iterate to tolerance), on every rung (the scenario's "
                 "integrator.newton_iterations is the linkage's, fidelity.newton_iterations the derived rungs')")->check(CLI::Range(0, 50));
  cmd.add_option("--jacobian-every", ov.jacobianEvery, "Jacobian every N steps (0 = first step only)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_option("--fidelity", ov.fidelity,
                 "Suspension model: linkage (the vehicle file's), kinematic or planar (derived from it at load "
                 "time), or auto (the cheapest within --error-budget, switched in mid-run where the scene needs it)")
      ->check(CLI::IsMember(fidelityChoices()));
  cmd.add_option("--error-budget", ov.errorBudget,
                 "With --fidelity auto: the error allowed against the linkage, % of peak (RMS of yaw rate and "
                 "lateral acceleration; default 10: the planar model where the scene allows it)")
      ->check(CLI::Range(0.0, 100.0));
  cmd.add_option("--vehicle", ov.vehicle, "Vehicle file replacing the scenario's")->check(CLI::ExistingFile);
  cmd.add_option("--driver", ov.driver,
                 "The path-following driver's steering law: pure_pursuit, or preview (MacAdam's preview driver as a "
                 "model-predictive controller on the car's single-track model; docs/STANDARD_TESTS.md)")
      ->check(CLI::IsMember({"pure_pursuit", "preview"}));
  cmd.add_option("--duration", ov.duration, "Manoeuvre duration, s")->check(CLI::Range(1e-3, 1e6));
  cmd.add_flag("--as-published", ov.asPublished,
               "The paper's Newton as published: the fixed count only, no Jacobian refresh or rescue "
               "when it stops contracting (Tables 3 and 4)");
  cmd.add_option("--settle", ov.settle, "Settling time before the manoeuvre, s")->check(CLI::Range(0.0, 1e4));
  addSetOption(cmd, ov.settings,
               "KEY=VALUE: set a key of the scenario (start.speed=\"80 km/h\", fidelity.suspension=planar) or, "
               "prefixed vehicle., of its vehicle (vehicle.springs[0].damping=9000); keys are dotted paths with [N] "
               "for array elements, values TOML (a bare word is a string), checked as in the files "
               "(docs/SCENARIOS.md, docs/VEHICLES.md). Repeatable; later ones win");
}

void addSetOption(CLI::App& cmd, std::vector<std::string>& settings, const std::string& help) {
  cmd.add_option("--set", settings, help)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("KEY=VALUE");
}

scenario::ScenarioSpec loadScenario(const std::string& path, const ScenarioOverrides& ov) {
  std::vector<config::Setting> settings;
  for (const std::string& s : ov.settings) settings.push_back(config::parseSetting(s));
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(path, settings);
  applyOverrides(ov, spec);
  return spec;
}

void applyOverrides(const ScenarioOverrides& ov, scenario::ScenarioSpec& spec) {
  auto& it = spec.integrator;
  integ::BdfOptions& bdf = it.bdf;
  if (ov.step) it.step = *ov.step;
  if (ov.tick) spec.tick = *ov.tick;
  if (ov.integrator)
    it.method = *ov.integrator == "bdf" ? scenario::IntegratorMethod::Bdf
                : *ov.integrator == "rk4" ? scenario::IntegratorMethod::Rk4
                                          : scenario::IntegratorMethod::SemiImplicitEuler;
  if (ov.order) bdf.order = *ov.order;
  if (ov.newton) bdf.newtonIterations = spec.fidelity.newtonIterations = *ov.newton;
  if (ov.jacobianEvery) bdf.jacobianEvery = *ov.jacobianEvery;
  if (ov.vehicle) spec.vehicleFile = std::filesystem::path(*ov.vehicle).lexically_normal().string();
  if (ov.duration) spec.duration = *ov.duration;
  if (ov.driver) {
    if (!spec.pathFollower.enabled)
      throw std::runtime_error("--driver " + *ov.driver + ": " + spec.sourceFile +
                               " has no path-following [driver] (its steering is scripted)");
    spec.pathFollower.law = *ov.driver == "preview" ? scenario::PathFollowerSpec::Law::Preview
                                                    : scenario::PathFollowerSpec::Law::PurePursuit;
  }
  if (ov.fidelity) scenario::parseFidelity(*ov.fidelity, spec.fidelity);
  if (ov.errorBudget) spec.fidelity.errorBudget = *ov.errorBudget / 100.0;
  if (ov.settle) spec.settleTime = *ov.settle;
  if (ov.asPublished) {  // the paper's fixed count on every rung
    bdf.refreshWhenNotContracting = false;
    spec.fidelity.newtonIterations = bdf.newtonIterations;
    spec.fidelity.stopWithinTolerance = false;
  }
  if (scenario::stepsPerTick(spec.tick, it.step) == 0) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "--step %g s does not divide the driver's tick of %g ms (%s): each tick runs a whole number of "
                  "steps (e.g. --step %g or %g, or give --tick a multiple of the step)",
                  it.step, spec.tick * 1e3, spec.sourceFile.c_str(), spec.tick, spec.tick / 2);
    throw std::runtime_error(text);
  }
}

}  // namespace bdfcar::app
