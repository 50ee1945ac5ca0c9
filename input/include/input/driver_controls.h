// A person's controls (controls.h) as the simulation's input for one tick
// (physics/scenario/driver_input.h, a plain struct): the steering as the
// car's normalised input, the gear requests, clutch and handbrake.
#pragma once

#include "input/controls.h"
#include "scenario/driver_input.h"

namespace bdfcar::input {

// steeringWheelFull: the car's steering-wheel angle at full input, rad
// (vehicle file, steering.steering_wheel_angle_full). A wheel whose mapping
// gives its rotation steers the car's wheel by its own angle (clamped at the
// car's full lock); other devices map their full range onto full lock. A
// clutch pedal is a device's clutch axis (the keyboard's clutch key only
// opens the automatic clutch); up wins over down in the same tick.
scenario::DriverInput toDriverInput(const Controls& c, double steeringWheelFull);

}  // namespace bdfcar::input
