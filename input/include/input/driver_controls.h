// A person's controls (controls.h) as the simulation's input for one tick
// (physics/scenario/driver_input.h, a plain struct): the steering as the
// car's normalised input, the gear requests, clutch and handbrake.
#pragma once

#include "input/controls.h"
#include "scenario/driver_input.h"

namespace bdfcar::input {

using scenario::CarSteering;

// The factor speed-sensitive steering applies at the car's speed (m/s, its
// magnitude is used): the linear law 1 - (1 - scale) * min(|speed| / s.speed, 1),
// or the grip law clamp(a L / (v^2 delta), scale, 1) (controls.h); exactly 1
// when off.
double speedSensitiveFactor(const SpeedSensitiveSteering& s, double carSpeed, const CarSteering& car);

// car.steeringWheelFull: the car's steering-wheel angle at full input, rad
// (vehicle file, steering.steering_wheel_angle_full). A wheel whose mapping
// gives its rotation steers the car's wheel by its own angle (clamped at the
// car's full lock); other devices map their full range onto full lock. Then
// speed-sensitive steering scales it by speedSensitiveFactor at carSpeed (the
// car's speed, m/s); off, the steering is untouched. A clutch pedal is a
// device's clutch axis (the keyboard's clutch key only opens the automatic
// clutch); up wins over down in the same tick.
scenario::DriverInput toDriverInput(const Controls& c, const CarSteering& car, double carSpeed);

}  // namespace bdfcar::input
