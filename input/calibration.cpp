// Captured raw axis values -> which axis is the steering and which the pedals.
#include "input/calibration.h"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

namespace bdfcar::input {
namespace {

// The pedals in the order a person is asked to press them.
constexpr Axis kPedalOrder[] = {Axis::Throttle, Axis::Brake, Axis::Clutch, Axis::Handbrake};

// Rest, extremes and first press of axis a.
AxisCapture capture(const std::vector<std::vector<int>>& samples, int stillSamples, std::size_t a) {
  AxisCapture c;
  std::vector<int> still;
  for (int t = 0; t < stillSamples; ++t) still.push_back(samples[t][a]);
  std::nth_element(still.begin(), still.begin() + still.size() / 2, still.end());
  c.rest = still[still.size() / 2];  // the median: a twitch during the still reading does not move it
  c.lo = c.hi = samples[0][a];
  for (const std::vector<int>& row : samples) c.lo = std::min(c.lo, row[a]), c.hi = std::max(c.hi, row[a]);
  const long far = std::max(c.hi - c.rest, c.rest - c.lo);
  for (std::size_t t = 0; t < samples.size() && far > 0; ++t)
    if (2L * std::labs(static_cast<long>(samples[t][a]) - c.rest) > far) {
      c.firstPress = static_cast<long>(t);
      break;
    }
  return c;
}

// Travel the same both ways from rest.
int symmetricTravel(const AxisCapture& c) { return std::min(c.rest - c.lo, c.hi - c.rest); }

bool moved(const AxisCapture& c) { return c.hi - c.lo >= kCalibrationMinTravel; }

// Rests within 10 % of its travel from one end.
bool restsAtAnEnd(const AxisCapture& c) { return 10L * symmetricTravel(c) <= static_cast<long>(c.hi - c.lo); }

// `base`'s settings of a control (deadzone, curve, ...), bound to `axis`.
AxisMapping fromBase(const DeviceMapping& base, Axis control, int axis) {
  AxisMapping a = base.axes[static_cast<int>(control)];
  if (!a.bound) {
    a = AxisMapping{};
    a.bound = true;
    if (control == Axis::Steering) a.invert = true;  // SDL reads + to the right; bdfcar steers + to the left
  }
  a.axis = axis;
  return a;
}

std::string ordinal(int n) {
  static const char* const names[] = {"1st", "2nd", "3rd", "4th"};
  return n < 4 ? names[n] : std::to_string(n + 1) + "th";
}

}  // namespace

// Steering by symmetric travel, pedals by rest at an end and press order (see the header).
Calibration calibrateAxes(const std::vector<std::vector<int>>& samples, int stillSamples, const DeviceMapping& base) {
  if (stillSamples < 1 || samples.size() <= static_cast<std::size_t>(stillSamples))
    throw std::invalid_argument("calibrateAxes: the still reading must be some, but not all, of the samples");
  const std::size_t axisCount = samples[0].size();
  for (const std::vector<int>& row : samples)
    if (row.size() != axisCount) throw std::invalid_argument("calibrateAxes: rows of different lengths");

  Calibration cal;
  cal.mapping = base;
  for (AxisMapping& a : cal.mapping.axes) a = AxisMapping{};
  for (std::size_t a = 0; a < axisCount; ++a) cal.axes.push_back(capture(samples, stillSamples, a));
  std::vector<bool> assigned(axisCount, false);

  int steering = -1;
  for (std::size_t a = 0; a < axisCount; ++a) {
    const AxisCapture& c = cal.axes[a];
    if (moved(c) && 2 * symmetricTravel(c) >= kCalibrationMinTravel &&
        (steering < 0 || symmetricTravel(c) > symmetricTravel(cal.axes[steering])))
      steering = static_cast<int>(a);
  }
  if (steering >= 0) {
    const AxisCapture& c = cal.axes[steering];
    AxisMapping s = fromBase(base, Axis::Steering, steering);
    const int h = symmetricTravel(c);
    s.rawMin = c.rest - h;
    s.rawMax = c.rest + h;
    cal.mapping.axes[static_cast<int>(Axis::Steering)] = s;
    cal.steeringFound = true;
    assigned[steering] = true;
    const int left = s.invert ? s.rawMin : s.rawMax, right = s.invert ? s.rawMax : s.rawMin;
    cal.report.push_back("steering: axis " + std::to_string(steering) + ", straight ahead at " +
                         std::to_string(c.rest) + ", full left at " + std::to_string(left) + ", full right at " +
                         std::to_string(right));
    // Noise and the raw range's own odd count (-32768..32767) are not worth a note; 5 % less one way is.
    const int longer = std::max(c.hi - c.rest, c.rest - c.lo);
    if (20L * (longer - h) > longer)
      cal.report.push_back("  turned " + std::to_string(longer) +
                           " one way but " + std::to_string(h) +
                           " the other: full lock is taken at the shorter; if that was not the wheel's lock, "
                           "calibrate again turning fully both ways");
  }

  std::vector<int> pedals;
  for (std::size_t a = 0; a < axisCount; ++a)
    if (!assigned[a] && moved(cal.axes[a]) && restsAtAnEnd(cal.axes[a]) && cal.axes[a].firstPress >= 0)
      pedals.push_back(static_cast<int>(a));
  std::stable_sort(pedals.begin(), pedals.end(),
                   [&](int x, int y) { return cal.axes[x].firstPress < cal.axes[y].firstPress; });
  for (std::size_t n = 0; n < pedals.size() && n < std::size(kPedalOrder); ++n) {
    const AxisCapture& c = cal.axes[pedals[n]];
    AxisMapping p = fromBase(base, kPedalOrder[n], pedals[n]);
    p.invert = false;  // the direction is in min / max
    p.rawMin = c.rest;
    p.rawMax = c.rest - c.lo < c.hi - c.rest ? c.hi : c.lo;
    cal.mapping.axes[static_cast<int>(kPedalOrder[n])] = p;
    assigned[pedals[n]] = true;
    cal.report.push_back(std::string(axisName(kPedalOrder[n])) + ": axis " + std::to_string(pedals[n]) +
                         ", released at " + std::to_string(p.rawMin) + ", fully down at " +
                         std::to_string(p.rawMax) + " (pressed " + ordinal(static_cast<int>(n)) + ")");
  }

  for (std::size_t a = 0; a < axisCount; ++a) {
    const AxisCapture& c = cal.axes[a];
    if (assigned[a] || !moved(c)) continue;
    cal.report.push_back("axis " + std::to_string(a) + ": moved " + std::to_string(c.lo) + " .. " +
                         std::to_string(c.hi) + " from rest " + std::to_string(c.rest) + " but " +
                         (restsAtAnEnd(c) ? "more pedals were pressed than there are controls"
                                          : "rests mid-travel and is not the steering") +
                         ": not assigned");
  }
  return cal;
}

}  // namespace bdfcar::input
