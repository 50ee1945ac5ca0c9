// The linear single-track ("bicycle") model of a car: the yaw and sideslip
// of a rigid body on two axles with linear tyres, steered at the front
// (Riekert and Schunck 1940; Milliken and Milliken, Race Car Vehicle
// Dynamics, ch. 5; Mitschke and Wallentowitz, ch. 27). What a driver model
// knows of the car it drives (the preview driver, preview_driver.h), and
// the closed forms the standard tests' calibrations are checked against.
//
// Lateral velocity vy (m/s, chassis y, at the centre of mass) and yaw rate r
// at forward speed u, road-wheel angle delta:
//   m (vy' + u r) = Ff + Fr,   Iz r' = a Ff - b Fr,
//   Ff = Cf (delta - (vy + a r) / u),   Fr = -Cr (vy - b r) / u.
#pragma once

#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

struct SingleTrack {
  double mass = 0;          // kg
  double yawInertia = 0;    // kg m^2 about the vertical through the centre of mass
  double a = 0, b = 0;      // m, centre of mass behind the front axle, ahead of the rear
  double frontStiffness = 0, rearStiffness = 0;  // N/rad per axle (both tyres)
  double roadWheelPerSteer = 0;  // rad of road-wheel angle per unit normalised steering input

  double wheelbase() const { return a + b; }
  // Understeer gradient K (rad of road-wheel angle per m/s^2 of lateral
  // acceleration): delta = L / R + K a_y in steady cornering.
  double understeerGradient() const;
  // Steady-state lateral acceleration per rad of road-wheel angle at speed u:
  // u^2 / (L + K u^2).
  double steadyLateralGain(double u) const;
  // (vy', r') at (vy, r), speed u, road-wheel angle delta.
  void derivatives(double u, double vy, double r, double delta, double& dvy, double& dr) const;
  // Lateral acceleration (vy' + u r) at that state.
  double lateralAcceleration(double u, double vy, double r, double delta) const;
  // Lateral acceleration's response to a steering ramp of `rate` (rad/s of
  // road-wheel angle), once its transient has died out, lags the steady
  // response to the angle by this many seconds: a_y(t) -> G (delta(t) -
  // rate * lag) (the transfer function's a1 - b1).
  double rampLag(double u) const;
};

// From a vehicle: its mass and yaw inertia (every body), the centre of mass
// between the axles (the vehicle sheet's), each axle's tyres' cornering
// stiffness at their static load, and the steering's road-wheel angle per
// input (the linkage's, at small angles).
SingleTrack singleTrack(const Vehicle& v);

}  // namespace bdfcar::vehicle
