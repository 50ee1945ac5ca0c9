// A person's controls (controls.h) as the simulation's input for one tick
// (physics/scenario/driver_input.h, a plain struct): the steering as the
// car's normalised input, the gear requests, clutch and handbrake.
#pragma once

#include "input/controls.h"
#include "scenario/driver_input.h"

namespace bdfcar::input {

// The factor speed-sensitive steering applies at the car's speed (m/s, its
// magnitude is used): 1 - (1 - scale) * min(|speed| / s.speed, 1); exactly 1
// when off (s.speed = 0).
double speedSensitiveFactor(const SpeedSensitiveSteering& s, double carSpeed);

// steeringWheelFull: the car's steering-wheel angle at full input, rad
// (vehicle file, steering.steering_wheel_angle_full). A wheel whose mapping
// gives its rotation steers the car's wheel by its own angle (clamped at the
// car's full lock); other devices map their full range onto full lock. Then
// speed-sensitive steering scales it by speedSensitiveFactor at carSpeed (the
// car's speed, m/s); off, the steering is untouched. A clutch pedal is a
// device's clutch axis (the keyboard's clutch key only opens the automatic
// clutch); up wins over down in the same tick.
scenario::DriverInput toDriverInput(const Controls& c, double steeringWheelFull, double carSpeed);

}  // namespace bdfcar::input
