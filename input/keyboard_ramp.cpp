#include "input/keyboard_ramp.h"

#include <algorithm>

namespace bdfcar::input {
namespace {

// `value` moved towards `target` by at most `step` (no overshoot).
double moveToward(double value, double target, double step) {
  return value < target ? std::min(target, value + step) : std::max(target, value - step);
}

// A pedal one tick later: up while held, down after release.
double rampPedal(const KeyboardRamps& r, bool held, double value, double dt) {
  return held ? moveToward(value, 1.0, r.pedalRiseRate * dt) : moveToward(value, 0.0, r.pedalFallRate * dt);
}

}  // namespace

// The keyboard's analog values one tick after `previous` (rates of keyboard.toml).
KeyboardAnalog rampKeyboard(const KeyboardRamps& r, const KeyboardHeld& held, const KeyboardAnalog& previous,
                            double dt) {
  KeyboardAnalog next;
  const int direction = (held.left ? 1 : 0) - (held.right ? 1 : 0);  // + = left
  next.steering = direction == 0 ? moveToward(previous.steering, 0.0, r.centreRate * dt)
                                 : moveToward(previous.steering, direction, r.steerRate * dt);
  next.throttle = rampPedal(r, held.throttle, previous.throttle, dt);
  next.brake = rampPedal(r, held.brake, previous.brake, dt);
  next.clutch = rampPedal(r, held.clutch, previous.clutch, dt);
  next.handbrake = rampPedal(r, held.handbrake, previous.handbrake, dt);
  return next;
}

}  // namespace bdfcar::input
