#include "scenario/transmission.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::scenario {

double Transmission::launchEngagement(double engineSpeed, double lockedSpeed) const {
  const double lo = 1.05 * spec_.engine.idleSpeed;
  return std::clamp((std::max(engineSpeed, lockedSpeed) - lo) / (spec_.clutch.launchSpeed - lo), 0.0, 1.0);
}

void Transmission::start(double output, double vx) {
  const vehicle::GearboxSpec& g = spec_.gearbox;
  state_ = TransmissionState{};
  state_.gear = 1;
  if (std::abs(vx) > kReverseSpeed)
    for (int k = 1; k <= g.gears(); ++k) {
      state_.gear = k;
      if (g.overall(k) * output <= g.upshiftSpeedLight) break;
    }
  state_.nextGear = state_.gear;
  const double locked = g.overall(state_.gear) * output;
  state_.engagement = launchEngagement(std::max(locked, spec_.engine.idleSpeed), locked);
}

void Transmission::beginShift(int to) {
  if (pedal_) {
    state_.gear = state_.nextGear = to;  // the driver works the clutch
    return;
  }
  state_.nextGear = to;
  state_.shiftClock = 0;
}

void Transmission::request(int direction, double vx, double output) {
  if (shifting()) return;
  const vehicle::GearboxSpec& g = spec_.gearbox;
  const int cur = state_.gear;
  int to = cur + (direction > 0 ? 1 : -1);
  // An automatic box has no neutral between first and reverse (D and R).
  if (g.automatic && to == 0) to = direction > 0 ? 1 : -1;
  to = std::clamp(to, -1, g.gears());
  if (to == cur) return;
  if (to == -1 && vx > kReverseSpeed) return;   // not into reverse while rolling forwards
  if (cur == -1 && to >= 1 && vx < -kReverseSpeed) return;  // nor into first while rolling backwards
  // Not down into a gear that would turn the engine past its limit.
  if (to >= 1 && g.overall(to) * output > spec_.engine.revLimit) return;
  beginShift(to);
}

vehicle::DrivelineCommand Transmission::update(const DriverInput& in, const DrivelineSpeeds& s, double h) {
  const vehicle::GearboxSpec& g = spec_.gearbox;
  pedal_ = in.clutchPedal;
  if (in.shift != 0) request(in.shift, s.vx, s.output);
  double throttle = std::clamp(in.throttle, 0.0, 1.0);
  // The schedule, on the engine speed the gear gives at the wheels' speed.
  if (g.automatic && !shifting() && state_.gear >= 1) {
    const double locked = g.overall(state_.gear) * s.output;
    const double up = g.upshiftSpeedLight + throttle * (g.upshiftSpeed - g.upshiftSpeedLight);
    if (locked > up && state_.gear < g.gears()) beginShift(state_.gear + 1);
    else if (locked < g.downshiftSpeed && state_.gear > 1) beginShift(state_.gear - 1);
  }
  const double locked = g.overall(state_.gear) * s.output;
  double target = launchEngagement(s.engine, locked);
  if (shifting()) {
    // Open over the first half with the throttle closed, change, close over the second.
    state_.shiftClock += h;
    const double T = spec_.clutch.shiftTime;
    const double phase = std::min(1.0, state_.shiftClock / T);
    if (phase >= 0.5) state_.gear = state_.nextGear;
    state_.engagement = std::min(std::abs(1.0 - 2.0 * phase), launchEngagement(s.engine, g.overall(state_.gear) * s.output));
    // The throttle closes with the clutch and opens again as it closes (no flare).
    if (phase < 0.5) throttle = 0.0;
    else throttle *= state_.engagement;
    if (state_.shiftClock >= T) state_.shiftClock = -1;
  } else if (in.clutchPedal) {
    state_.engagement = 1.0 - std::clamp(in.clutch, 0.0, 1.0);
  } else {
    const double step = kEngagementRate * h;
    state_.engagement += std::clamp(target - state_.engagement, -step, step);
    // A clutch key held over the automatic clutch opens it as far as it is pressed.
    state_.engagement = std::min(state_.engagement, 1.0 - std::clamp(in.clutch, 0.0, 1.0));
  }
  vehicle::DrivelineCommand c;
  c.throttle = throttle;
  c.ratio = g.overall(state_.gear);
  c.clutchCapacity = state_.engagement * spec_.clutch.maxTorque;
  return c;
}

}  // namespace bdfcar::scenario
