// The driver's commands for one 10 ms tick, from a person (input/ -> app) or
// from a scripted / path-following driver. Plain data, SI units.
#pragma once

namespace bdfcar::scenario {

struct DriverInput {
  double steer = 0.0;     // normalised steering [-1, 1], + = left (maps to rack travel)
  double throttle = 0.0;  // [0, 1]
  double brake = 0.0;     // [0, 1]
  // For a car with a powertrain (ignored without one):
  double handbrake = 0.0; // [0, 1], on the rear wheels
  double clutch = 0.0;    // [0, 1], 1 = pedal down (disengaged)
  // A clutch pedal: the driver works the clutch (engagement 1 - clutch).
  // Without one the clutch is automatic, and `clutch` (a key) only opens it further.
  bool clutchPedal = false;
  int shift = 0;          // +1 up, -1 down: a request made in this tick
  bool operator==(const DriverInput&) const = default;
};

// What a person's controls need of the car to become its input: a wheel's
// own angle against the car's full lock, and speed-sensitive steering's grip
// law (input/driver_controls.h). Simulation::carSteering gives the car's.
struct CarSteering {
  double steeringWheelFull = 0.0;  // rad, the steering-wheel angle at full input (vehicle file)
  double roadWheelFull = 0.0;      // rad, the road-wheel angle of full input near straight ahead
  double wheelbase = 0.0;          // m
};

}  // namespace bdfcar::scenario
