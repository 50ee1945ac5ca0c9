#include "input/axis_response.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::input {

// Control value of a raw axis value (see the header for the formula).
double axisResponse(const AxisMapping& m, Axis control, int raw) {
  const bool bipolar = control == Axis::Steering;
  const double lo = m.rawMin, hi = m.rawMax;  // hi < lo is allowed: a reversed pedal
  double x;
  if (bipolar) {
    const double centre = 0.5 * (lo + hi), halfSpan = 0.5 * (hi - lo);
    x = std::clamp((raw - centre) / halfSpan, -1.0, 1.0);
    if (m.invert) x = -x;
  } else {
    x = std::clamp((raw - lo) / (hi - lo), 0.0, 1.0);
    if (m.invert) x = 1.0 - x;
  }
  const double sign = x < 0.0 ? -1.0 : 1.0;
  double magnitude = std::abs(x);
  // Rescale past the deadzone so that the full range is still reachable.
  magnitude = magnitude <= m.deadzone ? 0.0 : (magnitude - m.deadzone) / (1.0 - m.deadzone);
  if (m.curve == Curve::Power) magnitude = std::pow(magnitude, m.exponent);
  return sign * std::min(1.0, m.gain * magnitude);
}

namespace {

// The raw value at which a pedal reads fully down.
int pressedEnd(const AxisMapping& p) { return p.invert ? p.rawMin : p.rawMax; }

}  // namespace

// rawMin is released unless the pedal is inverted (x -> 1 - x).
int releasedEnd(const AxisMapping& p) { return p.invert ? p.rawMax : p.rawMin; }

// Further towards the released end than the pressed end lies.
int moreReleased(const AxisMapping& p, int a, int b) {
  return releasedEnd(p) < pressedEnd(p) ? std::min(a, b) : std::max(a, b);
}

// The released end moved to a rest strictly inside the travel.
AxisMapping pedalFromRest(const AxisMapping& p, int rest) {
  const int lo = std::min(releasedEnd(p), pressedEnd(p)), hi = std::max(releasedEnd(p), pressedEnd(p));
  if (rest <= lo || rest >= hi) return p;
  AxisMapping moved = p;
  (p.invert ? moved.rawMax : moved.rawMin) = rest;
  return moved;
}

}  // namespace bdfcar::input
