// The driver's commands for one 10 ms tick, from a person (input/ -> app) or
// from a scripted / path-following driver. Plain data, SI units.
#pragma once

namespace bdfcar::scenario {

struct DriverInput {
  double steer = 0.0;     // normalised steering [-1, 1], + = left (maps to rack travel)
  double throttle = 0.0;  // [0, 1]
  double brake = 0.0;     // [0, 1]
};

}  // namespace bdfcar::scenario
