#include "input/driver_controls.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::input {

double speedSensitiveFactor(const SpeedSensitiveSteering& s, double carSpeed, const CarSteering& car) {
  if (s.lateralAcceleration > 0.0) {
    // The grip law: full input asks for s.lateralAcceleration (v^2 delta / L).
    // A car whose steering is not known (no road-wheel angle) is left whole.
    const double turn = carSpeed * carSpeed * std::abs(car.roadWheelFull);
    if (!(turn > 0.0) || !(car.wheelbase > 0.0)) return 1.0;
    return std::clamp(s.lateralAcceleration * car.wheelbase / turn, s.scale, 1.0);
  }
  // Linear from 1 at a standstill to `scale` at `speed`, held above it.
  if (!(s.speed > 0.0)) return 1.0;
  return 1.0 - (1.0 - s.scale) * std::min(std::abs(carSpeed) / s.speed, 1.0);
}

scenario::DriverInput toDriverInput(const Controls& c, const CarSteering& car, double carSpeed) {
  scenario::DriverInput in;
  in.steer = std::isfinite(c.steeringWheelAngle) && car.steeringWheelFull > 0
                 ? std::clamp(c.steeringWheelAngle / car.steeringWheelFull, -1.0, 1.0)
                 : c.steering;
  // Off, the input is not touched at all: recordings and replays stay bit for bit those of before.
  if (c.speedSensitive.on()) in.steer *= speedSensitiveFactor(c.speedSensitive, carSpeed, car);
  in.throttle = c.throttle;
  in.brake = c.brake;
  in.handbrake = c.handbrake;
  in.clutch = c.clutch;
  in.clutchPedal = c.hasClutch && c.source != DeviceKind::Keyboard;
  in.shift = c.gearUp ? 1 : c.gearDown ? -1 : 0;
  return in;
}

}  // namespace bdfcar::input
