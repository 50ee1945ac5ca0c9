#include "input/driver_controls.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::input {

// Linear from 1 at a standstill to `scale` at `speed`, held above it.
double speedSensitiveFactor(const SpeedSensitiveSteering& s, double carSpeed) {
  if (!(s.speed > 0.0)) return 1.0;
  return 1.0 - (1.0 - s.scale) * std::min(std::abs(carSpeed) / s.speed, 1.0);
}

scenario::DriverInput toDriverInput(const Controls& c, double steeringWheelFull, double carSpeed) {
  scenario::DriverInput in;
  in.steer = std::isfinite(c.steeringWheelAngle) && steeringWheelFull > 0
                 ? std::clamp(c.steeringWheelAngle / steeringWheelFull, -1.0, 1.0)
                 : c.steering;
  // Off, the input is not touched at all: recordings and replays stay bit for bit those of before.
  if (c.speedSensitive.speed > 0.0) in.steer *= speedSensitiveFactor(c.speedSensitive, carSpeed);
  in.throttle = c.throttle;
  in.brake = c.brake;
  in.handbrake = c.handbrake;
  in.clutch = c.clutch;
  in.clutchPedal = c.hasClutch && c.source != DeviceKind::Keyboard;
  in.shift = c.gearUp ? 1 : c.gearDown ? -1 : 0;
  return in;
}

}  // namespace bdfcar::input
