// Ray set-up and hit reporting shared by the mesh and heightfield terrains.
#include "terrain/bullet/ray_segment.h"

#include <algorithm>
#include <cmath>

#include "terrain/bullet/bullet_terrain.h"

namespace bdfcar::terrain {

namespace {
// |n.z| below this counts as a vertical face (unit normals).
constexpr double kVerticalNormalZ = 1e-9;
// How far outside a triangle, in barycentric terms, a ray still hits it: rays
// through a shared edge hit one of the two triangles despite rounding.
constexpr double kEdge = 1e-9;
}  // namespace

// Unit direction and a finite length; invalid for rays that cannot hit.
RaySegment makeRaySegment(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) {
  RaySegment ray;
  const double norm = direction.norm();
  ray.valid = norm > 0.0 && std::isfinite(norm) && from.allFinite() && maxDistance > 0.0;  // false for NaN too
  if (!ray.valid) return ray;
  ray.from = from;
  ray.unit = direction / norm;
  ray.length = std::min(maxDistance, kMaxRayLength);
  return ray;
}

NearestTriangleHit::NearestTriangleHit(const btVector3& from, const btVector3& to) : from_(from), delta_(to - from) {}

// Solves from + f delta = v0 + u e1 + v e2 (Moller & Trumbore 1997) and keeps
// the smallest f in [0, 1] with u, v, 1 - u - v >= -kEdge; on a tie the
// lowest triangle index, so the result does not depend on the order the
// triangles come in (Bullet's tree walk, the mesh's plan-view grid).
void NearestTriangleHit::processTriangle(btVector3* t, int, int index) {
  const btVector3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const btVector3 n = e1.cross(e2);
  if (n.length2() == 0.0) return;  // degenerate triangle
  const btVector3 p = delta_.cross(e2);
  const btScalar det = e1.dot(p);
  if (det == 0.0) return;  // ray parallel to the triangle's plane
  const btVector3 s = from_ - t[0];
  const btScalar u = s.dot(p) / det;
  if (u < -kEdge || u > 1.0 + kEdge) return;
  const btVector3 q = s.cross(e1);
  const btScalar v = delta_.dot(q) / det;
  if (v < -kEdge || u + v > 1.0 + kEdge) return;
  const btScalar f = e2.dot(q) / det;
  if (!(f >= 0.0 && f <= 1.0) || (hit && (f > fraction || (f == fraction && index >= triangle)))) return;
  hit = true;
  fraction = f;
  normal = n;
  triangle = index;
}

// Point and distance from the hit fraction; the normal turned to point up
// (out of the ground), or for a vertical face back towards the ray origin.
Hit toHit(const RaySegment& ray, const NearestTriangleHit& nearest, double friction) {
  Hit h;
  h.friction = friction;
  if (!nearest.hit) return h;
  h.hit = true;
  h.distance = nearest.fraction * ray.length;
  h.point = ray.from + h.distance * ray.unit;
  Eigen::Vector3d n = Eigen::Vector3d(nearest.normal.x(), nearest.normal.y(), nearest.normal.z()).normalized();
  const bool vertical = std::abs(n.z()) <= kVerticalNormalZ;
  if ((!vertical && n.z() < 0.0) || (vertical && n.dot(ray.unit) > 0.0)) n = -n;
  h.normal = n;
  return h;
}

}  // namespace bdfcar::terrain
