// Keyboard steering and pedals: held keys move the values at the rates of
// keyboard.toml instead of jumping (deterministic: the tick length is an input).
#pragma once

#include "input/mapping.h"

namespace bdfcar::input {

struct KeyboardHeld {
  bool left = false, right = false, throttle = false, brake = false, clutch = false, handbrake = false;
};

struct KeyboardAnalog {
  double steering = 0.0, throttle = 0.0, brake = 0.0, clutch = 0.0, handbrake = 0.0;
};

// The keyboard's analog values one tick of dt seconds after `previous`:
// one steer key held -> towards +-1 at steerRate; none or both -> towards 0
// at centreRate; a pedal key held -> towards 1 at pedalRiseRate, else towards
// 0 at pedalFallRate.
KeyboardAnalog rampKeyboard(const KeyboardRamps& ramps, const KeyboardHeld& held,
                            const KeyboardAnalog& previous, double dt);

}  // namespace bdfcar::input
