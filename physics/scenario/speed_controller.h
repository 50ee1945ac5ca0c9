// PI speed hold on each driven wheel, as in the reference runs:
// T = Kp e + Ki integral(e dt), e = v_ref - v_x (chassis COM velocity along
// chassis x). The torque may go negative (it then acts as a brake). The
// integral advances by explicit Euler once per step, from the state at the
// start of the step.
#pragma once

namespace bdfcar::scenario {

struct SpeedControllerGains {
  double kp = 600.0;  // N m per (m/s), per driven wheel
  double ki = 300.0;  // N m per m
};

class SpeedController {
 public:
  SpeedController(double target, const SpeedControllerGains& g) : target_(target), g_(g) {}
  // Torque to hold during the next step of length h, given the current speed.
  double torque(double vx, double h) {
    const double e = target_ - vx;
    const double T = g_.kp * e + g_.ki * integral_;
    integral_ += e * h;
    return T;
  }
  void setTarget(double v) { target_ = v; }
  double target() const { return target_; }
  void reset() { integral_ = 0; }
  // The integral of the speed error (m): the controller's run state.
  double integral() const { return integral_; }
  void setIntegral(double x) { integral_ = x; }

 private:
  double target_;
  SpeedControllerGains g_;
  double integral_ = 0;
};

}  // namespace bdfcar::scenario
