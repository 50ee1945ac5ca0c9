// The steering system between a driver's command and the rack (the power
// assist), so that a step or a flip-flop input is a hard input rather than a
// tear in the model: the rack follows the command like a position servo with
// the vehicle's response time, its speed and acceleration bounded by the
// vehicle file's maximum rack speed and acceleration. Within a driver tick
// the rack moves with constant acceleration, so its motion is C1 (velocity
// continuous) and the rack driver constraint stays smooth for Newton.
//
// A person's and the path follower's commands go through it; the scenario's
// scripted signals (the reference runs' prescribed rack) do not.
#pragma once

#include "vehicle/vehicle_spec.h"

namespace bdfcar::scenario {

// In normalised steering units (steer = rack travel / rack travel at full input).
struct SteeringLimits {
  double responseTime = 0.03;  // s
  double maxRate = 1.0;        // 1/s
  double maxAcceleration = 1.0;  // 1/s^2
};

SteeringLimits steeringLimits(const vehicle::SteeringSpec& s);

// The constant acceleration (1/s^2) over the next tick of a rack at `steer`
// moving at `rate`, following `command`: toward the rate that closes the
// error within the response time (at least two ticks, which keeps the
// tick-by-tick servo stable), bounded in rate and acceleration.
double steeringAcceleration(const SteeringLimits& l, double steer, double rate, double command, double tick);

// Rack motion of one driver tick: steer(t) = s0 + r0 (t - t0) + a (t - t0)^2 / 2.
struct RackSegment {
  bool scripted = true;        // the scenario's analytic signal instead
  double t0 = 0, s0 = 0, r0 = 0, a = 0;
  bool operator==(const RackSegment&) const = default;
  double steer(double t) const { return s0 + (r0 + 0.5 * a * (t - t0)) * (t - t0); }
  double rate(double t) const { return r0 + a * (t - t0); }
};

}  // namespace bdfcar::scenario
