// The Bullet terrains, built from data that checkTerrainData accepted
// (internal: makeTerrain is the public way in).
#pragma once

#include <memory>

#include "terrain/terrain.h"
#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

// A bounding-volume tree over data.vertices / data.triangles, and the plan
// grid rays straight down go through (planGrid = false: the tree for every
// ray, the grid's reference in tests/test_terrain.cpp).
std::unique_ptr<Terrain> makeMeshTerrain(const TerrainData& data, bool planGrid = true);
// Whether t is such a mesh with its plan grid built (a mesh of few
// triangles, or one whose triangles span many cells each, keeps the tree).
bool hasPlanGrid(const Terrain& t);

// Bullet's heightfield over data.heights.
std::unique_ptr<Terrain> makeHeightfieldTerrain(const TerrainData& data);

// The ground's plane and its pieces, each in its own frame (ground_terrain.cpp).
std::unique_ptr<Terrain> makeGroundTerrain(const TerrainData& data);

}  // namespace bdfcar::terrain
