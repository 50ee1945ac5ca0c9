// The one place that picks a Terrain implementation for loaded data.
#include "terrain/bullet/bullet_shapes.h"
#include "terrain/bullet/bullet_terrain.h"

namespace bdfcar::terrain {

// Checked data to the matching implementation.
std::unique_ptr<Terrain> makeTerrain(const TerrainData& data) {
  checkTerrainData(data);
  switch (data.kind) {
    case TerrainKind::Plane: return std::make_unique<PlaneTerrain>(data.planePoint, data.planeNormal, data.friction);
    case TerrainKind::Mesh: return makeMeshTerrain(data);
    case TerrainKind::Heightfield: return makeHeightfieldTerrain(data);
  }
  return nullptr;
}

}  // namespace bdfcar::terrain
