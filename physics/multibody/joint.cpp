#include "multibody/joint.h"

#include <cmath>
#include "portable_math.h"

namespace bdfcar::mb {

Mat3 quatToMatrix(const double* wxyz) {
  return Quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).toRotationMatrix();
}

namespace {

void storeQuat(const Quat& q, double* out) {
  const Quat n = q.normalized();
  out[0] = n.w();
  out[1] = n.x();
  out[2] = n.y();
  out[3] = n.z();
}

Quat loadQuat(const double* wxyz) { return Quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]); }

// Rotation vector of the relative rotation q0^-1 q (in q0's frame), |result| <= pi.
Vec3 relativeRotation(const double* q0, const double* q) {
  Quat r = loadQuat(q0).conjugate() * loadQuat(q);
  if (r.w() < 0) r.coeffs() = -r.coeffs();
  const Vec3 v = r.vec();
  const double s = v.norm();
  if (s < 5e-3) {
    // 2 atan(x) / x with x = s / w by series (next term below 1e-20 here).
    const double x2 = s * s / (r.w() * r.w());
    return v * (2.0 / r.w() * (1.0 - x2 * (1.0 / 3.0 - x2 * (1.0 / 5.0 - x2 * (1.0 / 7.0 - x2 / 9.0)))));
  }
  return v * (2.0 * pm::atan2(s, r.w()) / s);
}

}  // namespace

void jointRelativePose(JointType type, const double* q, Mat3& Rj, Vec3& dj) {
  switch (type) {
    case JointType::Tabulated1:
    case JointType::Tabulated2:  // from the joint's table (kinematics.cpp); identity here
      Rj.setIdentity();
      dj.setZero();
      break;
    case JointType::Revolute:
      Rj = rotZ(q[0]);
      dj.setZero();
      break;
    case JointType::Prismatic:
      Rj.setIdentity();
      dj = Vec3(0, 0, q[0]);
      break;
    case JointType::Cylindrical:
      Rj = rotZ(q[0]);
      dj = Vec3(0, 0, q[1]);
      break;
    case JointType::Universal:
      Rj = rotX(q[0]) * rotY(q[1]);
      dj.setZero();
      break;
    case JointType::Spherical:
      Rj = quatToMatrix(q);
      dj.setZero();
      break;
    case JointType::Free:
      dj = Vec3(q[0], q[1], q[2]);
      Rj = quatToMatrix(q + 3);
      break;
    case JointType::Planar:
      dj = Vec3(q[0], q[1], 0.0);
      Rj = rotZ(q[2]);
      break;
  }
}

void jointSubspace(JointType type, const double* q, SubspaceBlock& Sj) {
  switch (type) {
    case JointType::Tabulated1:
    case JointType::Tabulated2:  // from the joint's table, written by updatePositions
      Sj.setZero(6, jointNv(type));
      break;
    case JointType::Revolute:
      Sj.resize(6, 1);
      Sj << 0, 0, 0, 0, 0, 1;
      break;
    case JointType::Prismatic:
      Sj.resize(6, 1);
      Sj << 0, 0, 1, 0, 0, 0;
      break;
    case JointType::Cylindrical:  // v = (theta_dot, s_dot)
      Sj.resize(6, 2);
      Sj.setZero();
      Sj(5, 0) = 1;
      Sj(2, 1) = 1;
      break;
    case JointType::Universal: {  // v = (alpha_dot about parent x, beta_dot about child y)
      Sj.resize(6, 2);
      Sj.setZero();
      const pm::SinCos r = pm::sincos(q[1]);
      Sj(3, 0) = r.c;
      Sj(5, 0) = r.s;
      Sj(4, 1) = 1;
      break;
    }
    case JointType::Spherical:
      Sj.resize(6, 3);
      Sj.setZero();
      Sj.bottomRows<3>().setIdentity();
      break;
    case JointType::Free:
      Sj.resize(6, 6);
      Sj.setIdentity();
      break;
    case JointType::Planar:  // v = (forward, sideways) in the child joint frame, rate about z
      Sj.resize(6, 3);
      Sj.setZero();
      Sj(0, 0) = 1;
      Sj(1, 1) = 1;
      Sj(5, 2) = 1;
      break;
  }
}

void jointRetract(JointType type, const double* q, const double* dq, double* out) {
  switch (type) {
    case JointType::Revolute:
    case JointType::Prismatic:
    case JointType::Tabulated1:
      out[0] = q[0] + dq[0];
      break;
    case JointType::Cylindrical:
    case JointType::Universal:
    case JointType::Tabulated2:
      out[0] = q[0] + dq[0];
      out[1] = q[1] + dq[1];
      break;
    case JointType::Spherical:
      storeQuat(loadQuat(q) * expQuat(Vec3(dq[0], dq[1], dq[2])), out);
      break;
    case JointType::Free: {
      const Mat3 R = quatToMatrix(q + 3);
      const Vec3 p = Vec3(q[0], q[1], q[2]) + R * Vec3(dq[0], dq[1], dq[2]);
      out[0] = p.x();
      out[1] = p.y();
      out[2] = p.z();
      storeQuat(loadQuat(q + 3) * expQuat(Vec3(dq[3], dq[4], dq[5])), out + 3);
      break;
    }
    case JointType::Planar: {
      const auto [s, c] = pm::sincos(q[2]);
      planarRetract(q, dq, s, c, out);
      break;
    }
  }
}

void jointLocal(JointType type, const double* base, const double* q, double* out) {
  switch (type) {
    case JointType::Revolute:
    case JointType::Prismatic:
    case JointType::Tabulated1:
      out[0] = q[0] - base[0];
      break;
    case JointType::Cylindrical:
    case JointType::Universal:
    case JointType::Tabulated2:
      out[0] = q[0] - base[0];
      out[1] = q[1] - base[1];
      break;
    case JointType::Spherical: {
      const Vec3 th = relativeRotation(base, q);
      out[0] = th.x();
      out[1] = th.y();
      out[2] = th.z();
      break;
    }
    case JointType::Free: {
      const Vec3 dp = loadQuat(base + 3).conjugate() * Vec3(q[0] - base[0], q[1] - base[1], q[2] - base[2]);
      const Vec3 th = relativeRotation(base + 3, q + 3);
      for (int i = 0; i < 3; ++i) {
        out[i] = dp(i);
        out[3 + i] = th(i);
      }
      break;
    }
    case JointType::Planar: {
      const auto [s, c] = pm::sincos(base[2]);
      planarLocal(base, q, s, c, out);
      break;
    }
  }
}

void planarRetract(const double* q, const double* dq, double s, double c, double* out) {
  // As the free joint: the translation increment is in the child frame.
  out[0] = q[0] + c * dq[0] - s * dq[1];
  out[1] = q[1] + s * dq[0] + c * dq[1];
  out[2] = q[2] + dq[2];
}

void planarLocal(const double* base, const double* q, double s, double c, double* out) {
  const double dx = q[0] - base[0], dy = q[1] - base[1];
  out[0] = c * dx + s * dy;
  out[1] = -s * dx + c * dy;
  out[2] = q[2] - base[2];
}

void jointLocalRate(JointType type, const double* delta, const double* v, double* out) {
  switch (type) {
    case JointType::Revolute:
    case JointType::Prismatic:
    case JointType::Tabulated1:
      out[0] = v[0];
      break;
    case JointType::Cylindrical:
    case JointType::Universal:
    case JointType::Tabulated2:
      out[0] = v[0];
      out[1] = v[1];
      break;
    case JointType::Spherical: {
      const Vec3 r = rightJacobianInverse(Vec3(delta[0], delta[1], delta[2])) * Vec3(v[0], v[1], v[2]);
      out[0] = r.x();
      out[1] = r.y();
      out[2] = r.z();
      break;
    }
    case JointType::Free: {
      // d/dt R0^T (p - p0) = R0^T R v_lin = exp(dtheta) v_lin.
      const Vec3 th(delta[3], delta[4], delta[5]);
      const Vec3 lin = expSO3(th) * Vec3(v[0], v[1], v[2]);
      const Vec3 ang = rightJacobianInverse(th) * Vec3(v[3], v[4], v[5]);
      for (int i = 0; i < 3; ++i) {
        out[i] = lin(i);
        out[3 + i] = ang(i);
      }
      break;
    }
    case JointType::Planar: {
      // d/dt Rz(a0)^T (p - p0) = Rz(a - a0) v_lin.
      const auto [s, c] = pm::sincos(delta[2]);
      out[0] = c * v[0] - s * v[1];
      out[1] = s * v[0] + c * v[1];
      out[2] = v[2];
      break;
    }
  }
}

}  // namespace bdfcar::mb
