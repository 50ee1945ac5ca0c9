// From a raw SDL axis value to a control value, as a mapping file says.
#pragma once

#include "input/controls.h"
#include "input/mapping.h"

namespace bdfcar::input {

// Control value of raw axis value `raw` through calibration, invert, deadzone,
// curve and gain. Steering is bipolar: x = (raw - centre) / half-span of
// [rawMin, rawMax], in [-1, 1]. Pedals are unipolar: x = (raw - rawMin) /
// (rawMax - rawMin), in [0, 1]. Then invert, then |x| <= deadzone -> 0 else
// (|x| - deadzone) / (1 - deadzone), then the curve, then gain, clamped.
double axisResponse(const AxisMapping& mapping, Axis control, int raw);

}  // namespace bdfcar::input
