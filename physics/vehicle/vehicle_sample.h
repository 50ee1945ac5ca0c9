// The measurable state of a vehicle at one instant: what the telemetry,
// the HUD, the drivers and the reference comparison read. Computed from a
// solution point (q, v, a) by one kinematic pass and one force evaluation.
#pragma once

#include <array>

#include "integrator/step_types.h"
#include "multibody/multibody_dae.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_forces.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::vehicle {

struct VehicleSample {
  double t = 0;
  Vec3 com = Vec3::Zero();              // chassis COM, world
  Vec3 chassisOrigin = Vec3::Zero();    // chassis reference frame, world
  Mat3 chassisRotation = Mat3::Identity();
  double roll = 0, pitch = 0, yaw = 0;  // Z-Y-X Euler angles of the chassis, rad
  double vx = 0, vy = 0;                // COM velocity in chassis axes, m/s
  double yawRate = 0;                   // chassis angular velocity about chassis z, rad/s
  double ay = 0;                        // COM acceleration along chassis y (kinematic), m/s^2
  double ax = 0;                        // COM acceleration along chassis x, m/s^2
  double ayHorizontal = 0;              // COM acceleration in the ground plane, normal to the heading
  double rack = 0;                      // rack displacement along chassis y, m
  double speed = 0;                     // |COM velocity|, m/s
  std::array<double, 4> Fz{}, Fx{}, Fy{}, alpha{}, kappa{}, steerAngle{}, spinRate{};
  std::array<bool, 4> inContact{};
  std::array<double, 4> driveTorque{};
  double rackForce = 0;                 // driver constraint multiplier, N
  // What an engineer reads off a corner (docs/TELEMETRY.md).
  double sideslip = 0;                  // atan2(vy, vx), rad
  double rollRate = 0, pitchRate = 0;   // chassis angular velocity about chassis x and y, rad/s
  std::array<double, 4> Mz{};           // tyre aligning moment, N m (contact frame)
  std::array<double, 4> camber{}, toe{};  // rad, relative to the chassis: + top out, + toe-in
  std::array<double, 4> travel{};       // wheel centre along chassis z from its design place, m, + bump
  std::array<double, 4> springForce{}, damperForce{}, stopForce{};  // N, the corner's suspension, + compressing
};

// Kinematics and forces of the accepted solution point. evaluated: dae's
// data already holds them (a residual evaluation at s, e.g. the closed-form
// planar model's multibodyPoint), not evaluated again.
VehicleSample sampleVehicle(const Vehicle& v, mb::MultibodyDae& dae, VehicleForces& forces,
                            const integ::SolutionPoint& s, bool evaluated = false);

// World poses and suspension segments for drawing (uses dae.data() as left by sampleVehicle).
VehicleView viewVehicle(const Vehicle& v, const mb::MultibodyDae& dae, const VehicleForces& forces, double t);

}  // namespace bdfcar::vehicle
