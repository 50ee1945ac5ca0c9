#include "multibody/spatial.h"

#include <cmath>
#include "portable_math.h"

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
    const pm::SinCos r = pm::sincos(t);
    a = r.s / t;
    b = (1.0 - r.c) / t2;
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
  const double theta = 2.0 * pm::atan2(s, q.w());
  return v * (theta / s);
}

Mat3 rightJacobianInverse(const Vec3& theta) {
  const double t2 = theta.squaredNorm();
  const Mat3 W = skew(theta);
  double c;  // Jr^-1 = I + W/2 + c W^2
  if (t2 < 2.5e-3) {
    // Series of 1/t^2 - (1 + cos t) / (2 t sin t); the next term is below
    // 1e-19 for |t| < 0.05 (a step's rotation is far smaller).
    c = 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 * (1.0 / 1209600.0)));
  } else {
    const double t = std::sqrt(t2);
    const pm::SinCos r = pm::sincos(t);
    c = 1.0 / t2 - (1.0 + r.c) / (2.0 * t * r.s);
  }
  return Mat3::Identity() + 0.5 * W + c * (W * W);
}

Quat expQuat(const Vec3& w) {
  const double t2 = w.squaredNorm();
  if (t2 < 1e-4) {
    // cos(t/2) and sin(t/2)/t by series: exact to round-off for |t| < 0.01
    // (next terms below 1e-20), no trigonometry on the step's path.
    const double c = 1.0 - t2 * (1.0 / 8.0 - t2 * (1.0 / 384.0 - t2 * (1.0 / 46080.0)));
    const double s = 0.5 - t2 * (1.0 / 48.0 - t2 * (1.0 / 3840.0 - t2 * (1.0 / 645120.0)));
    return Quat(c, s * w.x(), s * w.y(), s * w.z());
  }
  const double t = std::sqrt(t2);
  const pm::SinCos h = pm::sincos(0.5 * t);
  const double s = h.s / t;
  return Quat(h.c, s * w.x(), s * w.y(), s * w.z());
}

Mat3 rotX(double a) {
  const auto [s, c] = pm::sincos(a);
  Mat3 m;
  m << 1, 0, 0, 0, c, -s, 0, s, c;
  return m;
}
Mat3 rotY(double a) {
  const auto [s, c] = pm::sincos(a);
  Mat3 m;
  m << c, 0, s, 0, 1, 0, -s, 0, c;
  return m;
}
Mat3 rotZ(double a) {
  const auto [s, c] = pm::sincos(a);
  Mat3 m;
  m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

}  // namespace bdfcar::mb
