#include "scenario/fidelity_policy.h"

#include <algorithm>
#include <cmath>
#include "portable_math.h"

namespace bdfcar::scenario {

double FidelityPolicy::roadNormalZ() {
  static const double z = pm::cos(kRoadSlope);
  return z;
}

FidelityPolicy::FidelityPolicy(const terrain::Terrain& terrain, double roadZ,
                               const std::array<Eigen::Vector2d, 4>& wheelOffsets,
                               const std::array<tyre::TyreParams, 4>& tyres, double lateralLevel)
    : terrain_(terrain), roadZ_(roadZ), offsets_(wheelOffsets), tyres_(tyres), lateralLevel_(lateralLevel) {}

bool FidelityPolicy::level(const Eigen::Vector2d& xy) const {
  const terrain::Hit h =
      terrain_.castRay(Eigen::Vector3d(xy.x(), xy.y(), roadZ_ + kRayAbove), -Eigen::Vector3d::UnitZ(), kRayLength);
  return h.hit && std::abs(h.point.z() - roadZ_) <= kRoadHeight && h.normal.z() >= roadNormalZ();
}

// Each wheel's scan points from `first` to `last` lie on a segment (linear
// in the distance): the box around it, with a rounding margin, asked of the
// terrain; the stretch is vouched for when every wheel's is. One box per
// wheel, not one around the four: a mesh answers from its plan grid at a
// cost that grows with the cells the box covers (terrain/bullet/
// mesh_terrain.cpp), and the four wheels' strips are a small part of the
// car's footprint. A box the terrain cannot
// vouch for is scanned ray by ray: the decisions are the rays' either way.
template <class Point>
bool FidelityPolicy::levelAhead(double first, double last, const Point& point) const {
  terrain::Terrain::LevelQuery q;
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(1e-6);
  q.zTop = roadZ_ + kRayAbove;
  q.zBottom = roadZ_ + kRayAbove - kRayLength;
  q.height = roadZ_;
  q.tolerance = kRoadHeight;
  q.minNormalZ = roadNormalZ();
  for (const Eigen::Vector2d& o : offsets_) {
    const Eigen::Vector2d a = point(o, first), b = point(o, last);
    q.lo = a.cwiseMin(b) - margin;
    q.hi = a.cwiseMax(b) + margin;
    if (!terrain_.levelOver(q)) return false;
  }
  return true;
}

double FidelityPolicy::peakFriction(int w, double road) const {
  PeakFriction& p = peak_[w];
  if (!(road == p.road)) p = {road, tyre::peakFriction(tyres_[w], road)};
  return p.mu;
}

void FidelityPolicy::refuse(State& s) {
  s.calm = 0;
  ++s.refused;
}

void FidelityPolicy::forceFull(State& s) {
  s.fullUntil = std::max(s.fullUntil, s.odometer + kMargin);
  s.calm = 0;
  ++s.missed;
}

FidelityPolicy::Decision FidelityPolicy::decide(State& s, const Eigen::Vector2d& com, double yaw, double speed,
                                                double yawRate, const std::array<vehicle::WheelContact, 4>& wheels,
                                                double tick) const {
  s.odometer += std::abs(speed) * tick;
  // Scan what has come into range: from where the last scan ended (or the
  // wheels, at the start) to the look-ahead, along the heading.
  const double reach = s.odometer + std::max(kMinLookAhead, std::abs(speed) * kLookAhead);
  const Eigen::Vector2d heading(pm::cos(yaw), pm::sin(yaw)), left(-heading.y(), heading.x());
  if (terrain_.levelEverywhere()) {
    s.scanned = reach;  // a level plane: nothing to find, nothing to ask
  } else {
    auto scanPoint = [&](const Eigen::Vector2d& o, double d) {
      return Eigen::Vector2d(com + o.x() * heading + o.y() * left + (d - s.odometer) * heading);
    };
    const double first = std::max(s.scanned, s.odometer);
    if (first <= reach) {
      // The terrain vouches for the whole stretch: the scan's positions, no
      // rays. Asked first as far as kScanAhead beyond the look-ahead, so that a
      // level road costs a query per wheel every few ticks, not every tick;
      // where that stretch is not level, as far as the look-ahead only (what
      // lies beyond is scanned when it comes into range, as always).
      const double ahead = reach + kScanAhead;
      const double last = levelAhead(first, ahead, scanPoint)   ? ahead
                          : levelAhead(first, reach, scanPoint) ? reach
                                                                : -1;
      for (double d = first; d <= last; d += kScanStep) s.scanned = d + kScanStep;
    }
    for (double d = std::max(s.scanned, s.odometer); d <= reach; d += kScanStep) {
      for (const Eigen::Vector2d& o : offsets_)
        if (!level(scanPoint(o, d))) s.fullUntil = std::max(s.fullUntil, d + kMargin);
      s.scanned = d + kScanStep;
    }
  }
  bool saturated = false;  // or a wheel in the air, or off the road plane, or beyond the certified range
  double lowestMu = INFINITY;
  for (int w = 0; w < 4; ++w) {
    const tyre::ContactPlane& g = wheels[w].plane;
    if (!g.valid || std::abs(g.point.z() - roadZ_) > kRoadHeight || g.normal.z() < roadNormalZ()) {
      s.fullUntil = std::max(s.fullUntil, s.odometer + kMargin);
      saturated = true;
      continue;
    }
    const vehicle::WheelContact& o = wheels[w];  // the accepted step's tyre
    if (!o.acceptedInContact) {  // a wheel off the ground: heave, roll and pitch matter
      saturated = true;
      continue;
    }
    const double mu = peakFriction(w, wheels[w].plane.friction);
    // |(Fx, Fy)| beyond the limit, compared squared (no root: this runs every tick).
    const double limit = kSaturation * mu * o.acceptedFz;
    saturated = saturated || limit < 0 || o.acceptedFx * o.acceptedFx + o.acceptedFy * o.acceptedFy > limit * limit;
    lowestMu = std::min(lowestMu, mu);
  }
  constexpr double kG = 9.81;
  saturated = saturated || std::abs(speed * yawRate) > lateralLevel_ * lowestMu * kG;
  if (saturated || s.odometer < s.fullUntil) {
    s.calm = 0;
    return Decision::Full;
  }
  s.calm += tick;
  return s.calm >= kCalm ? Decision::Planar : Decision::Hold;
}

}  // namespace bdfcar::scenario
