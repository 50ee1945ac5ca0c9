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

}  // namespace bdfcar::input
