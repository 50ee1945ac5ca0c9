// The analytic plane: the reference every other terrain is tested against.
#include <algorithm>
#include <cmath>

#include "terrain/terrain.h"

namespace bdfcar::terrain {

PlaneTerrain::PlaneTerrain(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double friction)
    : point_(point), normal_(normal.normalized()), friction_(friction) {}

// Ray/plane intersection: s = n.(p - from) / n.d with d the unit direction;
// the plane is two-sided (a ray from below hits it too), the normal is the plane's.
Hit PlaneTerrain::castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const {
  Hit h;
  h.friction = friction_;
  // A unit direction as it is (most rays are straight down: no square root
  // and division, the same d as direction / 1).
  const double length2 = direction.squaredNorm();
  if (!(length2 > 0.0) || !std::isfinite(length2)) return h;
  const Eigen::Vector3d d = length2 == 1.0 ? direction : Eigen::Vector3d(direction / std::sqrt(length2));
  const double approach = normal_.dot(d);
  // Parallel rays (also those lying in the plane) have no single first hit.
  if (approach == 0.0) return h;
  const double s = normal_.dot(point_ - from) / approach;
  if (!(s >= 0.0 && s <= maxDistance)) return h;  // also rejects NaN
  h.hit = true;
  h.point = from + s * d;
  h.normal = normal_;
  h.distance = s;
  return h;
}

// Linear in x and y: within the tolerance at the box's corners is within it
// everywhere over the box (a margin for the rays' rounding). The rays then
// meet it inside their span, which reaches past the tolerance.
bool PlaneTerrain::levelOver(const LevelQuery& q) const {
  if (!(normal_.z() >= q.minNormalZ) || !(normal_.z() > 0.0)) return false;
  constexpr double kMargin = 1e-9;  // m
  const double reach = std::min(q.zTop - q.height, q.height - q.zBottom);
  if (!(q.tolerance < reach)) return false;
  for (int k = 0; k < 4; ++k) {
    const double x = k & 1 ? q.hi.x() : q.lo.x(), y = k & 2 ? q.hi.y() : q.lo.y();
    const double z = point_.z() - (normal_.x() * (x - point_.x()) + normal_.y() * (y - point_.y())) / normal_.z();
    if (!(std::abs(z - q.height) <= q.tolerance - kMargin)) return false;
  }
  return true;
}

}  // namespace bdfcar::terrain
