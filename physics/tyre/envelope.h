// The enveloping contact: the effective road plane a tyre feels over its
// contact patch, instead of the road under one point.
//
// A tyre rolling over a short obstacle (a curb edge, a cleat, a pothole's
// rim) wraps around it: the axle rises before the wheel centre reaches the
// edge and more gently than a rigid point would follow, and the force tilts
// back while it climbs. The tandem elliptical cam model of Schmeitz (A. J. C.
// Schmeitz, "A semi-empirical three-dimensional model of the pneumatic tyre
// rolling over arbitrarily uneven road surfaces", PhD thesis, TU Delft, 2004;
// H. B. Pacejka, "Tyre and Vehicle Dynamics", 3rd ed., 2012, section 10.2)
// describes this geometrically: two cams, each the lower half of a
// superellipse |x/a|^c + |z/b|^c = 1 (the tyre's contour), stand a distance
// l_s apart along the wheel plane; each rests on the road profile (its lowest
// contour touching it, never below it); their mean height is the effective
// road height under the wheel, their difference over l_s the effective
// forward slope. The lateral slope is the profile's, across the wheel plane.
//
// Here the cams ride on a profile sampled once per step along the wheel
// plane (RoadProfile, from the terrain's rays), and are placed at the wheel's
// position in every residual: the ground follows the wheel through the Newton
// iterations (the road inside the step), from data fetched once per step.
//
// Without the tyre's measured contour the cams are its unloaded circle
// (a = b = R0, c = 2) and l_s is the static contact length, the chord of that
// circle at the deflection of a quarter of the car's weight over the tyre's
// vertical stiffness. On a plane of any slope the effective plane is that
// plane exactly (the cams' offset on a slope, their support function, is
// taken out), so on long road waves the envelope and the point agree.
#pragma once

#include <Eigen/Core>
#include <array>

#include "tyre/tyre.h"

namespace bdfcar::tyre {

// As the vehicle file gives it (tyres.NAME.contact and envelope_*); zero
// lengths are derived from the tyre (resolveEnvelope).
struct EnvelopeSpec {
  bool on = false;          // false: the point contact
  double halfLength = 0;    // a, m (0: the unloaded radius)
  double halfHeight = 0;    // b, m (0: the unloaded radius)
  double order = 2;         // c (2: an ellipse)
  double base = 0;          // l_s, m, the cams' distance (0: the static contact length)
  double spacing = 0.05;    // m, the road lattice's node spacing (and the profile's sample spacing)
  bool operator==(const EnvelopeSpec&) const = default;
};

// The cams of one tyre, every length resolved.
struct Envelope {
  bool on = false;
  double a = 0, b = 0, c = 2, base = 0, spacing = 0.05;
  double dual = 2;  // c / (c - 1): the exponent of the cams' support function
};

// The static contact length: the chord of the unloaded circle at the
// deflection load / stiffness.
double staticContactLength(double unloadedRadius, double verticalStiffness, double load);
Envelope resolveEnvelope(const EnvelopeSpec& spec, double unloadedRadius, double verticalStiffness, double staticLoad);

// The road along a wheel plane for one step: heights sampled along the
// horizontal line through `origin` in direction `heading`, at s0 + k ds.
struct RoadProfile {
  static constexpr int kCapacity = 256;
  static constexpr double kNoGround = -1e30;  // a sample's height where no ground was found
  bool valid = false;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Eigen::Vector2d heading = Eigen::Vector2d::UnitX();  // unit, horizontal
  double s0 = 0, ds = 0;
  int n = 0;
  std::array<double, kCapacity> z{};      // m, the road's height at each sample
  std::array<double, kCapacity> cross{};  // the road's slope across the line (dz per m to the heading's left)
  double friction = 0.8;                  // at the sample under the line's origin
  // Every sample on one line of this slope (to 1 nm: a level or evenly
  // sloped road), where a cam's height is the line's plus its offset.
  bool linear = false;
  double slope = 0;
  bool operator==(const RoadProfile&) const = default;
};

// The height of a cam's lowest point when the cam, centred at s along the
// profile, rests on it; kNoGround where no sample lies under it.
// T double or ad::Dual (envelope.cpp).
template <typename T>
T camHeight(const Envelope& e, const RoadProfile& p, const T& s);
inline double camHeight(const Envelope& e, const RoadProfile& p, double s) { return camHeight<double>(e, p, s); }
// Marks p linear where its samples are all ground on one line.
void findLine(RoadProfile& p);

// The effective road height, forward and lateral slope under a wheel centre
// (world); false where neither cam finds ground.
template <typename T>
struct EffectiveRoadT {
  T height = T(0.0), forwardSlope = T(0.0), lateralSlope = T(0.0);
};
using EffectiveRoad = EffectiveRoadT<double>;
template <typename T>
bool effectiveRoad(const Envelope& e, const RoadProfile& p, const Vec3T<T>& centre, EffectiveRoadT<T>& out);
inline bool effectiveRoad(const Envelope& e, const RoadProfile& p, const Eigen::Vector3d& centre, EffectiveRoad& out) {
  return effectiveRoad<double>(e, p, centre, out);
}

// The same as the plane the tyre models read: through the effective height
// under the centre, normal to the effective slopes.
// T double or ad::Dual (a closed form's Jacobian: the plane's derivative in the centre).
template <typename T>
ContactPlaneT<T> effectivePlane(const Envelope& e, const RoadProfile& p, const Vec3T<T>& centre);
inline ContactPlane effectivePlane(const Envelope& e, const RoadProfile& p, const Eigen::Vector3d& centre) {
  return effectivePlane<double>(e, p, centre);
}

}  // namespace bdfcar::tyre
