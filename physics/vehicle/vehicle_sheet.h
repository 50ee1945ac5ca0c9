// The vehicle sheet an engineer reads first (`bdfcar info VEHICLE`), from
// the linkage and the models derived from it (planar_model.h), not from
// hand-entered figures: geometry at rest, mass and centre of mass, static
// axle loads, wheel and ride rates, ride frequencies, roll centres, roll
// stiffness, steering ratio and Ackermann.
#pragma once

#include <array>
#include <string>

#include "vehicle/planar_model.h"

namespace bdfcar::vehicle {

struct VehicleSheet {
  double mass = 0;                        // kg
  double wheelbase = 0;                   // m, between the axles' contact points at rest
  std::array<double, 2> track{};          // m, front, rear
  double comHeight = 0;                   // m, centre of mass above the ground at rest
  double comBehindFrontAxle = 0;          // m
  std::array<double, 2> axleLoad{};       // N, front, rear, at rest on level ground
  std::array<double, 4> wheelRate{};      // N/m, suspension alone, at the static travel
  std::array<double, 4> rideRate{};       // N/m, in series with the tyre
  std::array<double, 2> rideFrequency{};  // Hz, sprung mass on the ride rates, per axle
  std::array<double, 2> rollCentre{};     // m above the ground
  double rollStiffness = 0;               // N m/rad
  double steeringRatio = 0;               // steering-wheel angle / mean front road-wheel angle, at small angles
  double ackermann = 0;                   // %, at 10 deg of inner road-wheel angle (100 = Ackermann, 0 = parallel)
};

// From a linkage vehicle; throws mb::ModelError as derivePlanar does.
VehicleSheet vehicleSheet(const Vehicle& linkage);
VehicleSheet vehicleSheet(const Vehicle& linkage, const PlanarDerivation& planar);

std::string describe(const VehicleSheet& s);

// Ackermann geometry: the outer road-wheel angle whose turn centre is the
// inner one's on the rear axle's line, and the percentage of it a steering
// gives (100 = Ackermann, 0 = parallel); angles in rad, inner > 0.
double ackermannOuter(double inner, double wheelbase, double track);
double ackermannPercent(double inner, double outer, double wheelbase, double track);
// "Ackermann 35 % at 10 deg inner road-wheel angle", or what a NaN (the
// steering does not reach 10 deg) means, for the sheets.
std::string ackermannText(double percent);

}  // namespace bdfcar::vehicle
