// The one place that picks a Terrain implementation for loaded data.
#include "terrain/bullet/bullet_shapes.h"
#include "terrain/bullet/bullet_terrain.h"

#include <LinearMath/btScalar.h>
#include <string>

namespace bdfcar::terrain {

namespace {

// The surface's own implementation with the friction patches laid over it:
// a hit inside a patch reports the patch's friction.
class PatchedFriction final : public Terrain {
 public:
  PatchedFriction(std::unique_ptr<Terrain> surface, std::vector<FrictionPatch> patches)
      : surface_(std::move(surface)), patches_(std::move(patches)) {}
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override {
    Hit h = surface_->castRay(from, direction, maxDistance);
    if (!h.hit) return h;
    for (auto p = patches_.rbegin(); p != patches_.rend(); ++p) {
      if (p->contains(h.point.x(), h.point.y())) {
        h.friction = p->friction;
        break;
      }
    }
    return h;
  }
  // The patches change friction, not the shape.
  bool levelEverywhere() const override { return surface_->levelEverywhere(); }
  bool levelOver(const LevelQuery& q) const override { return surface_->levelOver(q); }
  bool surfacesLevelOver(const LevelQuery& q) const override { return surface_->surfacesLevelOver(q); }

 private:
  std::unique_ptr<Terrain> surface_;
  std::vector<FrictionPatch> patches_;
};

std::unique_ptr<Terrain> makeSurface(const TerrainData& data) {
  switch (data.kind) {
    case TerrainKind::Plane: return std::make_unique<PlaneTerrain>(data.planePoint, data.planeNormal, data.friction);
    case TerrainKind::Mesh: return makeMeshTerrain(data);
    case TerrainKind::Heightfield: return makeHeightfieldTerrain(data);
    case TerrainKind::Ground: return makeGroundTerrain(data);
  }
  return nullptr;
}

}  // namespace

// Checked data to the matching implementation.
std::unique_ptr<Terrain> makeTerrain(const TerrainData& data) {
  checkTerrainData(data);
  std::unique_ptr<Terrain> surface = makeSurface(data);
  // A ground's plane carries its patches itself (ground_terrain.cpp): they are not for its pieces.
  if (data.frictionPatches.empty() || data.kind == TerrainKind::Ground) return surface;
  return std::make_unique<PatchedFriction>(std::move(surface), data.frictionPatches);
}

std::string bulletVersion() {
  const int v = btGetVersion();  // major * 100 + minor
  return std::to_string(v / 100) + "." + std::to_string(v % 100);
}

}  // namespace bdfcar::terrain
