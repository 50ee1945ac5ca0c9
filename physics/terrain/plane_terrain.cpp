// The analytic plane: the reference every other terrain is tested against.
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
  const double length = direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return h;
  const Eigen::Vector3d d = direction / length;
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

}  // namespace bdfcar::terrain
