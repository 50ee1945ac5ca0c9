#include "scenario/steering_system.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::scenario {

SteeringLimits steeringLimits(const vehicle::SteeringSpec& s) {
  const double full = std::abs(s.rackTravelFull);
  return {s.responseTime, s.maxRackSpeed / full, s.maxRackAcceleration / full};
}

double steeringAcceleration(const SteeringLimits& l, double steer, double rate, double command, double tick) {
  const double horizon = std::max(l.responseTime, 2.0 * tick);
  const double wanted = std::clamp((command - steer) / horizon, -l.maxRate, l.maxRate);
  double a = std::clamp((wanted - rate) / tick, -l.maxAcceleration, l.maxAcceleration);
  // The rate at the end of the tick stays within the maximum rack speed.
  a = std::clamp(a, (-l.maxRate - rate) / tick, (l.maxRate - rate) / tick);
  return a;
}

}  // namespace bdfcar::scenario
