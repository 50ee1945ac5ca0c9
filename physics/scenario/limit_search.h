// The highest speed at which a run passes (ISO 3888-2's figure: the highest
// entry speed with no cone down), searched between two speeds: both ends
// first, then the bracket [highest pass, lowest fail] cut into jobs + 1
// parts at a time (bisection with one job), each trial a whole run, the
// jobs on threads of their own, until the bracket is no wider than the
// resolution. A car that fails at the lowest speed gets that answer, one
// that passes at the highest gets that; the search always ends (each round
// narrows the bracket by at least half).
//
// Passing is taken as monotone in speed, as the standard does; where the
// trials say otherwise (a pass above a fail), the bracket is the lowest
// failing speed and the highest passing speed below it, and `nonMonotone`
// says so.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace bdfcar::scenario {

struct LimitSearchSpec {
  double from = 30 / 3.6, to = 100 / 3.6;  // m/s
  double resolution = 0.5 / 3.6;           // m/s
  int jobs = 1;                            // trials run at once
};

struct LimitTrial {
  double speed = 0;     // m/s
  bool passed = false;
  std::string verdict;  // what the trial function said
};

struct LimitResult {
  bool anyPass = false;     // some speed in the range passes
  bool allPass = false;     // the highest speed passes
  double highestPass = 0;   // m/s (when anyPass)
  double lowestFail = 0;    // m/s, the first failing speed above it (when !allPass)
  bool nonMonotone = false; // a pass was seen above a fail
  std::vector<LimitTrial> trials;  // in the order run
  std::string describe() const;    // one line, km/h
};

// trial(speed) -> passed, with its verdict; called from several threads at
// once when jobs > 1 (it must not share state between calls). An exception
// from a trial reaches the caller after its round.
using LimitTrialFunction = std::function<LimitTrial(double speed)>;
LimitResult searchLimit(const LimitSearchSpec& spec, const LimitTrialFunction& trial);

struct ScenarioSpec;
// A course scenario at entry speed v (m/s): its start and its speed hold at
// v, the hold's release (the throttle let go at the entry gate) and the
// duration scaled so that the car covers the same ground.
ScenarioSpec courseScenarioAt(const ScenarioSpec& base, double v);
// One trial: the course scenario run at v, passed when through the exit
// gate with no corner out and no cone down; the telemetry written where given.
LimitTrial courseTrial(const ScenarioSpec& base, double v, const std::string& telemetry = "");

}  // namespace bdfcar::scenario
