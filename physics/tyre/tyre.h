// What every tyre model reads and returns: a model maps (wheel pose and
// velocities, local terrain plane) to a force and a moment on the spindle,
// and may own transient slip states, advanced once per accepted step
// (declared here: SlipState). The models themselves are a closed set
// (tyre_model.h); the first is Fiala (fiala.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace bdfcar::tyre {

using Vec3 = Eigen::Vector3d;

// The ground under a wheel for one step: a plane from the terrain ray query.
struct ContactPlane {
  bool valid = false;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, out of the ground
  double friction = 0.8;        // terrain mu
  bool operator==(const ContactPlane&) const = default;
};

// Wheel state in the world frame.
struct WheelKinematics {
  Vec3 centre = Vec3::Zero();          // wheel centre C (spindle origin)
  Vec3 spinAxis = Vec3::UnitY();       // unit spin axis n (spindle y)
  Vec3 centreVelocity = Vec3::Zero();  // velocity of C
  double spinRate = 0.0;               // absolute angular velocity of the spindle about n (rolling forward > 0)
};

// Transient slips (tyre deflections over relaxation lengths), used at low
// speed where the slip definitions are singular.
struct SlipState {
  double kappa = 0.0;     // longitudinal transient slip
  double tanAlpha = 0.0;  // lateral transient slip (tan of the slip angle)
  // False while the wheel runs above the low-speed range, where the slips are
  // algebraic: the transient slips then start from the algebraic ones.
  bool active = true;
  bool operator==(const SlipState&) const = default;
};

struct TyreOutput {
  bool inContact = false;
  Vec3 force = Vec3::Zero();        // world, applied at `point`
  Vec3 point = Vec3::Zero();        // application point (world)
  Vec3 moment = Vec3::Zero();       // world, a pure couple
  // Contact-frame diagnostics (telemetry).
  Vec3 contactPoint = Vec3::Zero();
  double Fx = 0, Fy = 0, Fz = 0, My = 0, Mz = 0;
  double kappa = 0, tanAlpha = 0;   // slips used by the force law (the slip angle's tangent)
  double slipAngle() const;         // alpha, rad (atan tanAlpha: for telemetry, off the step's path)
  double deflection = 0;            // vertical tyre deflection delta, m
  double vx = 0, vsx = 0, vsy = 0;  // wheel-centre forward speed and slip velocities, m/s
  SlipState slipState;              // transient slips at the end of this evaluation
  bool operator==(const TyreOutput&) const = default;
};


}  // namespace bdfcar::tyre
