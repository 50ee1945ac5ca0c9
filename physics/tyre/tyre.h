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

// The types below are written for a scalar type T: double on the step's
// path, ad::Dual where a closed form differentiates its residual
// (autodiff.h); the plain names are the double ones.
template <typename T>
using Vec3T = Eigen::Matrix<T, 3, 1>;

// The ground under a wheel for one step: a plane from the terrain ray query.
template <typename T>
struct ContactPlaneT {
  bool valid = false;
  Vec3T<T> point = Vec3T<T>::Zero();
  Vec3T<T> normal = Vec3T<T>::UnitZ();  // unit, out of the ground
  double friction = 0.8;                // terrain mu
  bool operator==(const ContactPlaneT&) const = default;
};
using ContactPlane = ContactPlaneT<double>;

// Wheel state in the world frame.
template <typename T>
struct WheelKinematicsT {
  Vec3T<T> centre = Vec3T<T>::Zero();          // wheel centre C (spindle origin)
  Vec3T<T> spinAxis = Vec3T<T>::UnitY();       // unit spin axis n (spindle y)
  Vec3T<T> centreVelocity = Vec3T<T>::Zero();  // velocity of C
  T spinRate = T(0.0);                         // absolute angular velocity of the spindle about n (rolling forward > 0)
};
using WheelKinematics = WheelKinematicsT<double>;

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

template <typename T>
struct TyreOutputT {
  bool inContact = false;
  Vec3T<T> force = Vec3T<T>::Zero();   // world, applied at `point`
  Vec3T<T> point = Vec3T<T>::Zero();   // application point (world)
  Vec3T<T> moment = Vec3T<T>::Zero();  // world, a pure couple
  // Contact-frame diagnostics (telemetry).
  Vec3T<T> contactPoint = Vec3T<T>::Zero();
  T Fx = T(0.0), Fy = T(0.0), Fz = T(0.0), My = T(0.0), Mz = T(0.0);
  T kappa = T(0.0), tanAlpha = T(0.0);  // slips used by the force law (the slip angle's tangent)
  double slipAngle() const;             // alpha, rad (atan tanAlpha: for telemetry, off the step's path)
  T deflection = T(0.0);                // vertical tyre deflection delta, m
  T vx = T(0.0), vsx = T(0.0), vsy = T(0.0);  // wheel-centre forward speed and slip velocities, m/s
  SlipState slipState;                  // transient slips at the end of this evaluation
  bool operator==(const TyreOutputT&) const = default;
};
using TyreOutput = TyreOutputT<double>;


}  // namespace bdfcar::tyre
