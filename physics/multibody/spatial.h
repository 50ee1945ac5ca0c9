// Spatial (6-D) algebra and SO(3) helpers for the recursive multibody algorithms.
//
// Conventions (as Pinocchio): a motion vector is (linear; angular), a force
// vector is (force; moment), both expressed in a body frame at the body
// origin. A Transform X maps motion from parent coordinates to child
// coordinates: E rotates parent -> child, r is the child origin in parent
// coordinates (Featherstone, "Rigid Body Dynamics Algorithms", ch. 2).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace bdfcar::mb {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Quat = Eigen::Quaterniond;

inline Mat3 skew(const Vec3& w) {
  Mat3 m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

// Rotation matrix exp(w^) (Rodrigues), exact for any |w|.
Mat3 expSO3(const Vec3& w);
// Rotation vector log(R), |result| <= pi.
Vec3 logSO3(const Mat3& R);
// Inverse right Jacobian of SO(3): d(theta)/dt = Jr^-1(theta) * omega_body
// for R(t) = R0 exp(theta(t)).
Mat3 rightJacobianInverse(const Vec3& theta);
// Quaternion of exp(w^).
Quat expQuat(const Vec3& w);

// Rotation about a coordinate axis.
Mat3 rotX(double angle);
Mat3 rotY(double angle);
Mat3 rotZ(double angle);

struct Transform {
  Mat3 E = Mat3::Identity();  // rotates parent coordinates into child coordinates
  Vec3 r = Vec3::Zero();      // child origin in parent coordinates

  // Motion (v; w) in parent coordinates -> child coordinates.
  Vec6 applyMotion(const Vec6& m) const {
    Vec6 out;
    const Vec3 w = m.tail<3>();
    out.head<3>().noalias() = E * (m.head<3>() + w.cross(r));
    out.tail<3>().noalias() = E * w;
    return out;
  }
  // Force (f; n) in child coordinates -> parent coordinates (X^T f).
  Vec6 applyTransposeForce(const Vec6& f) const {
    Vec6 out;
    const Vec3 fp = E.transpose() * f.head<3>();
    out.head<3>() = fp;
    out.tail<3>().noalias() = E.transpose() * f.tail<3>() + r.cross(fp);
    return out;
  }
  // The 6x6 motion transform matrix (for composite inertias).
  Mat6 motionMatrix() const {
    Mat6 X;
    X.topLeftCorner<3, 3>() = E;
    X.topRightCorner<3, 3>().noalias() = -E * skew(r);
    X.bottomLeftCorner<3, 3>().setZero();
    X.bottomRightCorner<3, 3>() = E;
    return X;
  }
};

// Spatial cross product for motions: v x m.
inline Vec6 crossMotion(const Vec6& v, const Vec6& m) {
  Vec6 out;
  const Vec3 w = v.tail<3>();
  out.head<3>() = w.cross(m.head<3>()) + v.head<3>().cross(m.tail<3>());
  out.tail<3>() = w.cross(m.tail<3>());
  return out;
}

// Spatial cross product for forces: v x* f.
inline Vec6 crossForce(const Vec6& v, const Vec6& f) {
  Vec6 out;
  const Vec3 w = v.tail<3>();
  out.head<3>() = w.cross(f.head<3>());
  out.tail<3>() = w.cross(f.tail<3>()) + v.head<3>().cross(f.head<3>());
  return out;
}

// Spatial inertia at the body origin of a body with mass m, centre of mass c
// and rotational inertia Ic about the centre of mass (all in body axes).
inline Mat6 spatialInertia(double m, const Vec3& c, const Mat3& Ic) {
  Mat6 I;
  const Mat3 cx = skew(c);
  I.topLeftCorner<3, 3>() = m * Mat3::Identity();
  I.topRightCorner<3, 3>() = -m * cx;
  I.bottomLeftCorner<3, 3>() = m * cx;
  I.bottomRightCorner<3, 3>() = Ic - m * cx * cx;
  return I;
}

}  // namespace bdfcar::mb
