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
};

// An infinite plane through `point` with unit normal `normal`.
class PlaneTerrain final : public Terrain {
 public:
  PlaneTerrain(const Eigen::Vector3d& point = Eigen::Vector3d::Zero(),
               const Eigen::Vector3d& normal = Eigen::Vector3d::UnitZ(), double friction = 0.8);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;
  bool levelEverywhere() const override { return normal_.z() == 1.0; }

 private:
  Eigen::Vector3d point_, normal_;
  double friction_;
};

}  // namespace bdfcar::terrain
