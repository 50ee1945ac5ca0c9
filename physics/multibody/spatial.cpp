#include "multibody/spatial.h"

#include <cmath>

namespace bdfcar::mb {

Mat3 expSO3(const Vec3& w) {
  const double t2 = w.squaredNorm();
  const Mat3 W = skew(w);
  double a, b;  // R = I + a W + b W^2
  if (t2 < 1e-12) {
    a = 1.0 - t2 / 6.0;
    b = 0.5 - t2 / 24.0;
  } else {
    const double t = std::sqrt(t2);
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t2;
  }
  return Mat3::Identity() + a * W + b * (W * W);
}

Vec3 logSO3(const Mat3& R) {
  // Via the quaternion: robust near pi as well as near 0.
  Quat q(R);
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Vec3 v = q.vec();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v;  // theta ~ 2 sin(theta/2)
  const double theta = 2.0 * std::atan2(s, q.w());
  return v * (theta / s);
}

Mat3 rightJacobianInverse(const Vec3& theta) {
  const double t2 = theta.squaredNorm();
  const Mat3 W = skew(theta);
  double c;  // Jr^-1 = I + W/2 + c W^2
  if (t2 < 1e-8) {
    c = 1.0 / 12.0 + t2 / 720.0;
  } else {
    const double t = std::sqrt(t2);
    c = 1.0 / t2 - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  }
  return Mat3::Identity() + 0.5 * W + c * (W * W);
}

Quat expQuat(const Vec3& w) {
  const double t = w.norm();
  if (t < 1e-8) {
    Quat q(1.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z());
    q.normalize();
    return q;
  }
  const double s = std::sin(0.5 * t) / t;
  return Quat(std::cos(0.5 * t), s * w.x(), s * w.y(), s * w.z());
}

Mat3 rotX(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 m;
  m << 1, 0, 0, 0, c, -s, 0, s, c;
  return m;
}
Mat3 rotY(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 m;
  m << c, 0, s, 0, 1, 0, -s, 0, c;
  return m;
}
Mat3 rotZ(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Mat3 m;
  m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

}  // namespace bdfcar::mb
