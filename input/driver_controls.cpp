#include "input/driver_controls.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::input {

scenario::DriverInput toDriverInput(const Controls& c, double steeringWheelFull) {
  scenario::DriverInput in;
  in.steer = std::isfinite(c.steeringWheelAngle) && steeringWheelFull > 0
                 ? std::clamp(c.steeringWheelAngle / steeringWheelFull, -1.0, 1.0)
                 : c.steering;
  in.throttle = c.throttle;
  in.brake = c.brake;
  in.handbrake = c.handbrake;
  in.clutch = c.clutch;
  in.clutchPedal = c.hasClutch && c.source != DeviceKind::Keyboard;
  in.shift = c.gearUp ? 1 : c.gearDown ? -1 : 0;
  return in;
}

}  // namespace bdfcar::input
