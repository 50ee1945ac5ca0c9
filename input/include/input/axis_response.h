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

// A pedal's raw value at its released end: rawMin, or rawMax when inverted.
int releasedEnd(const AxisMapping& pedal);

// Of two raw readings of a pedal, the one further towards its released end.
int moreReleased(const AxisMapping& pedal, int a, int b);

// A pedal read from where it rests: where `rest` lies strictly inside the
// travel, it becomes the released end (a pedal resting at mid-range where the
// file expects an end reads 0, not 50 %, and the travel from there to the
// pressed end spans 0..1); a rest at or beyond the released end, or at the
// pressed end, leaves the mapping as it is.
AxisMapping pedalFromRest(const AxisMapping& pedal, int rest);

}  // namespace bdfcar::input
