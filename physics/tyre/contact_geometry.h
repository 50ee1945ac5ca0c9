// A wheel's single-point contact as the tyre models read it (the reference
// spec's 7.1, with the local ground normal in place of e_z): the disc of
// radius R0 in the wheel plane, its lowest point against the ground plane,
// the contact frame (x_c the heading in the ground plane, y_c to its left,
// z_c the normal) and the wheel centre's velocity in it; and the normal
// load's zero corner, rounded.
#pragma once

#include <cmath>
#include <optional>

#include "autodiff.h"
#include "tyre/tyre.h"

namespace bdfcar::tyre {

// The normal load's corner at zero rounded over this many newtons: a wheel
// striking a curb or landing switches contact inside a step, and Newton
// cannot converge across a kink. The difference is eps^2 / (4 Fz): below
// 0.01 N at the loads of a manoeuvre.
inline constexpr double kContactSmoothing = 10.0;   // N
inline constexpr double kAirborneClearance = 0.01;  // m above the ground: no contact at all

template <typename T>
struct ContactGeometryT {
  Vec3T<T> xc, yc;         // heading and its left in the ground plane
  Vec3T<T> down;           // down in the wheel plane (n x x_c)
  T delta = T(0.0);        // the disc's penetration, m
  T vx = T(0.0), vy = T(0.0), vz = T(0.0);  // wheel-centre velocity in the contact frame
};
using ContactGeometry = ContactGeometryT<double>;

// nullopt: no ground, the centre below it, or the wheel lying flat.
template <typename T>
inline std::optional<ContactGeometryT<T>> contactGeometry(const WheelKinematicsT<T>& w, const ContactPlaneT<T>& g,
                                                          double R0) {
  if (!g.valid) return std::nullopt;
  const Vec3T<T>& n = w.spinAxis;
  const Vec3T<T>& ez = g.normal;
  const Vec3T<T> nxz = n.cross(ez);
  const T heightOfCentre = (w.centre - g.point).dot(ez);
  if (ad::value(nxz.squaredNorm()) < 1e-3 || ad::value(heightOfCentre) <= 0) return std::nullopt;
  ContactGeometryT<T> c;
  c.xc = nxz.normalized();
  c.down = n.cross(c.xc);
  const Vec3T<T> bottom = w.centre + R0 * c.down;
  c.delta = (g.point - bottom).dot(ez);
  c.yc = ez.cross(c.xc);
  const Vec3T<T>& v = w.centreVelocity;
  c.vx = v.dot(c.xc);
  c.vy = v.dot(c.yc);
  c.vz = v.dot(ez);
  return c;
}

// The normal load from `raw` (spring and damper, or a load the model
// gives: `given`), its zero corner rounded; nullopt when the wheel is
// clear of the ground.
template <typename T>
inline std::optional<T> smoothedLoad(const T& raw, const T& delta, bool given) {
  using std::sqrt;
  if ((!given && ad::value(delta) <= -kAirborneClearance) || ad::value(raw) < -1e3 * kContactSmoothing)
    return std::nullopt;
  return T(0.5 * (raw + sqrt(raw * raw + kContactSmoothing * kContactSmoothing)));
}

}  // namespace bdfcar::tyre
