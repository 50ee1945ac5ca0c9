// Short runs of a vehicle's rungs that the ladder's derivation and
// certificate share: a manoeuvre on flat ground at the scene's integrator
// settings, run on any model derived from the linkage, and its steady state.
#pragma once

#include <string>
#include <vector>

#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "vehicle/vehicle_builder.h"

namespace bdfcar::scenario {

constexpr double kRungRunSpeed = 80.0 / 3.6;  // m/s, the handling manoeuvres' speed
constexpr double kRungRunFriction = 0.8;      // the flat plane's road friction

// The scene's vehicle and integrator, 80 km/h held by the speed control on
// flat ground, 1 s of settling, 4 s long, no input yet.
ScenarioSpec rungRunBase(const ScenarioSpec& scene);
// A steering ramp to a road-wheel angle (rad) in 0.2 s from t = 0.5 s.
SignalSpec roadWheelRamp(double angle);
SignalSpec signalTable(std::vector<double> times, std::vector<double> values);

// What the rungs' runs depend on besides the models: the scene's vehicle
// file and settings, its integrator settings and tick (a key for the
// per-process caches of the derivation and the certificate).
std::string rungRunsKey(const ScenarioSpec& scene);

// The run of s on `model` (the linkage itself or a rung derived from it);
// a failure (also one that throws) is a RunResult with ok = false.
RunResult runOnModel(const ScenarioSpec& s, const vehicle::Vehicle& linkage, const vehicle::Vehicle& model);

// Means over the last second of a run: lateral acceleration (m/s^2) and roll (rad).
struct SteadyState {
  double ay = 0, roll = 0;
  bool ok = false;
};
SteadyState steadyState(const RunResult& r);

}  // namespace bdfcar::scenario
