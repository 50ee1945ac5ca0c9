// `bdfcar input --calibrate` as numbers: the raw readings of a device's axes,
// captured while a person first holds still, then turns the wheel lock to
// lock and presses each pedal in turn -> which axis is which control, and its
// calibrated ends. Pure: samples in, mapping out (the capture is calibrate.cpp).
#pragma once

#include <string>
#include <vector>

#include "input/mapping.h"

namespace bdfcar::input {

// Raw counts two extremes must lie apart for an axis to count as moved (1/8
// of the raw range): less is noise, or a control nobody touched.
inline constexpr int kCalibrationMinTravel = 8192;

// What the capture saw of one raw axis.
struct AxisCapture {
  int rest = 0;          // the median of the still reading
  int lo = 0, hi = 0;    // the extremes over the whole capture
  long firstPress = -1;  // the first sample more than half-way from rest to the far extreme; -1: none
};

struct Calibration {
  DeviceMapping mapping;            // `base` with the axes found (see calibrateAxes)
  std::vector<AxisCapture> axes;    // per raw axis, in axis order
  std::vector<std::string> report;  // what was assigned, and what moved but was not, a line each
  bool steeringFound = false;       // false: no axis turned both ways from its rest; nothing to write
};

// samples[t][a]: raw axis a at sample t (every row as long as the first); the
// first stillSamples rows (at least 1, fewer than all) are the still reading.
// The rules:
// - steering: of the axes whose extremes lie kCalibrationMinTravel apart, the
//   one with the largest symmetric travel h = min(rest - lo, hi - rest), at
//   least half that each way; min / max = rest -/+ h, so both extremes reach
//   full lock and the rest reads straight ahead;
// - pedals: the other moved axes that rest at one end (within 10 % of their
//   travel), in the order in which they were first pressed half-way:
//   throttle, brake, clutch, handbrake; min = the rest (released), max = the
//   far extreme (max < min for a pedal whose reading falls), invert off.
// `base` is the mapping the device used: its kind, name filter, actions and
// force feedback are kept, and per control its deadzone, curve, gain, the
// steering's invert (SDL reads + to the right: true when base has no steering)
// and rotation_deg. Controls not found are left unbound.
Calibration calibrateAxes(const std::vector<std::vector<int>>& samples, int stillSamples, const DeviceMapping& base);

}  // namespace bdfcar::input
