// PI speed hold on each driven wheel, as in the reference runs:
// T = Kp e + Ki integral(e dt), e = v_ref - v_x (chassis COM velocity along
// chassis x). The torque may go negative (it then acts as a brake). The
// integral advances by explicit Euler once per step, from the state at the
// start of the step.
//
// What a test driver's speed hold also does ([speed_control], docs/SCENARIOS.md):
//  - it acts between a start and an end time (before and after, no torque:
//    the car coasts, or the [brake] input brakes it), and its integral
//    starts from zero when it takes over;
//  - its target may ramp from `target` to `rampTo` over a time span (the
//    slowly increasing speed of ISO 4138);
//  - its torque stays within the driveline's limit per driven wheel, and
//    while it is held at the limit the integral stops growing (anti-windup:
//    conditional integration), so the hold does not wind up against a brake
//    or a slope it cannot beat. Below the limit the law is exactly the PI
//    above (the reference runs never reach it).
#pragma once

#include <cmath>
#include <limits>

namespace bdfcar::scenario {

struct SpeedControllerGains {
  double kp = 600.0;  // N m per (m/s), per driven wheel
  double ki = 300.0;  // N m per m
};

struct SpeedProfile {
  double target = 0;                                            // m/s
  double start = -std::numeric_limits<double>::infinity();     // s, manoeuvre time
  double end = std::numeric_limits<double>::infinity();        // s
  double rampTo = std::numeric_limits<double>::quiet_NaN();    // m/s; NaN: no ramp
  double rampStart = 0, rampDuration = 0;                      // s
  // The target at time t.
  double at(double t) const {
    if (std::isnan(rampTo) || t <= rampStart) return target;
    if (t >= rampStart + rampDuration) return rampTo;
    return target + (rampTo - target) * (t - rampStart) / rampDuration;
  }
  bool active(double t) const { return t >= start && t < end; }
};

class SpeedController {
 public:
  // integral: where its run state lives (the integral of the speed error, m;
  // a RunState's). limit: the largest |torque| per driven wheel (N m;
  // infinity: none).
  SpeedController(const SpeedProfile& p, const SpeedControllerGains& g, double& integral,
                  double limit = std::numeric_limits<double>::infinity())
      : profile_(p), g_(g), limit_(limit), integral_(integral) {}
  // Torque to hold during the next step [t, t + h], given the current speed.
  double torque(double vx, double h, double t) {
    if (!profile_.active(t)) {
      integral_ = 0;  // a later phase starts afresh
      return 0;
    }
    const double e = profile_.at(t) - vx;
    const double T = g_.kp * e + g_.ki * integral_;
    if (std::abs(T) > limit_) {
      // Saturated: integrate only what brings the torque back inside.
      if (e * T < 0) integral_ += e * h;
      return std::copysign(limit_, T);
    }
    integral_ += e * h;
    return T;
  }
  double target(double t) const { return profile_.at(t); }
  bool active(double t) const { return profile_.active(t); }
  void reset() { integral_ = 0; }
  double integral() const { return integral_; }

 private:
  SpeedProfile profile_;
  SpeedControllerGains g_;
  double limit_;
  double& integral_;
};

}  // namespace bdfcar::scenario
