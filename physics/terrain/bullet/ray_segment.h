// What the Bullet terrains share: the ray as a segment, the callback that
// keeps the nearest triangle hit, and the conversion to a Hit (internal).
#pragma once

#include <BulletCollision/CollisionShapes/btTriangleCallback.h>

#include <Eigen/Core>

#include "terrain/terrain.h"

namespace bdfcar::terrain {

// from + s * unit, 0 <= s <= length; valid = false for a zero, infinite or NaN ray.
struct RaySegment {
  bool valid = false;
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), unit = Eigen::Vector3d::UnitZ();
  double length = 0.0;
  Eigen::Vector3d end() const { return from + length * unit; }
};

RaySegment makeRaySegment(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance);

inline btVector3 toBullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

// Receives the triangles Bullet finds along the ray (its tree walk or grid
// walk) and keeps the nearest one the segment crosses. The triangle test is
// ours (Moller-Trumbore with a tolerance of 1e-9 in barycentric terms):
// btTriangleRaycastCallback's edge tolerance grows with triangle area and
// lets a large face reach millimetres past a curb edge.
class NearestTriangleHit final : public btTriangleCallback {
 public:
  NearestTriangleHit(const btVector3& from, const btVector3& to);
  void processTriangle(btVector3* triangle, int partId, int triangleIndex) override;

  bool hit = false;
  btScalar fraction = 1.0;  // of the segment, at the nearest hit
  btVector3 normal{0, 0, 1};  // of the nearest triangle, by its winding, not unit
  int triangle = -1;          // its index

 private:
  btVector3 from_, delta_;
};

// The Hit of a finished query along `ray` (a miss if the callback saw nothing).
Hit toHit(const RaySegment& ray, const NearestTriangleHit& nearest, double friction);

// One query: the ray moved into the shape's frame (whose origin sits at
// shapeOrigin in the world), walk(nearest, from, to) feeding the shape's
// triangles along it to `nearest`, the result back as a world Hit.
template <class Walk>
Hit castThroughShape(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance,
                     const Eigen::Vector3d& shapeOrigin, double friction, Walk&& walk) {
  const RaySegment ray = makeRaySegment(from, direction, maxDistance);
  const btVector3 a = toBullet(ray.from - shapeOrigin), b = toBullet(ray.end() - shapeOrigin);
  NearestTriangleHit nearest(a, b);
  if (ray.valid) walk(nearest, a, b);
  return toHit(ray, nearest, friction);
}

}  // namespace bdfcar::terrain
