// Terrain as the physics sees it: a ray query returning the surface point,
// normal and friction. Implementations: an analytic plane (here, for unit
// tests and flat roads) and Bullet meshes / heightfields (terrain/bullet/,
// the only code that includes Bullet).
#pragma once

#include <Eigen/Core>

namespace bdfcar::terrain {

struct Hit {
  bool hit = false;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // world, m
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // unit, pointing out of the ground
  double friction = 0.8;                             // surface friction coefficient mu
  double distance = 0.0;                             // along the ray from its origin, m
};

class Terrain {
 public:
  virtual ~Terrain() = default;
  // First surface hit along from + s * direction, 0 <= s <= maxDistance
  // (direction need not be unit; distance is in metres along it).
  virtual Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const = 0;
  // True when the whole terrain is one level plane (nothing to look for
  // ahead of a car on it: scenario/fidelity_policy.h).
  virtual bool levelEverywhere() const { return false; }
  // True when it is certain that every ray cast straight down through the
  // box (x, y in [lo, hi]) from zTop to zBottom meets ground within
  // q.tolerance of height q.height whose unit normal's z is at least
  // q.minNormalZ: a whole patch of road answered at once instead of ray by
  // ray (scenario/fidelity_policy.h scans the road ahead). False when the
  // terrain cannot tell; the caller then casts its rays. Never true where
  // one of those rays would find anything else.
  struct LevelQuery {
    Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();
    double zTop = 1, zBottom = -1;  // the rays' span, m
    double height = 0, tolerance = 0, minNormalZ = 1;
  };
  virtual bool levelOver(const LevelQuery& /*q*/) const { return false; }
  // The same for a piece of a ground (ground_terrain.cpp), whose holes show
  // the ground's plane: every surface this terrain has in the box between
  // zBottom and zTop is such ground (none at all counts).
  virtual bool surfacesLevelOver(const LevelQuery& /*q*/) const { return false; }
};

// An infinite plane through `point` with unit normal `normal`.
class PlaneTerrain final : public Terrain {
 public:
  PlaneTerrain(const Eigen::Vector3d& point = Eigen::Vector3d::Zero(),
               const Eigen::Vector3d& normal = Eigen::Vector3d::UnitZ(), double friction = 0.8);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;
  bool levelEverywhere() const override { return normal_.z() == 1.0; }
  bool levelOver(const LevelQuery& q) const override;

 private:
  Eigen::Vector3d point_, normal_;
  double friction_;
};

}  // namespace bdfcar::terrain
