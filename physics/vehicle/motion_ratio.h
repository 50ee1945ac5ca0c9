// Suspension motion ratios at design: for each spring-damper, the rate of
// change of its length per unit vertical travel of its wheel centre
// (dL / dz, chassis held, rack held). Computed from the null space of the
// constraint Jacobian, so it holds for any topology the data describes.
// Used to make a spring moved to another body equivalent (k' = k (MR / MR')^2).
#pragma once

#include <string>
#include <vector>

#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

struct MotionRatio {
  std::string element;  // spring-damper name
  int wheel = -1;       // 0..3 (FL FR RL RR), -1 if it does not move with one wheel
  double ratio = 0;     // dL / dz_wheel
};

std::vector<MotionRatio> motionRatios(const Vehicle& v);

// Fills the layout's suspension channels of a linkage (VehicleLayout::
// springCorner, wheelCentreAtDesign) from its design.
void indexSuspensionChannels(Vehicle& v);

// Mean road-wheel steer angle of the front wheels per unit normalised
// steering input (rad), from the kinematics: small rack travels either side
// of centre with the wheels at their design height (as kc_rig.h's steering
// ratio); the same figure on every rung derived from a linkage.
double roadWheelAnglePerSteer(const Vehicle& v);

}  // namespace bdfcar::vehicle
