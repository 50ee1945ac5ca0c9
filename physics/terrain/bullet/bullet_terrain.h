// Terrain over Bullet collision shapes, used for ray queries and nothing
// else: btBvhTriangleMeshShape for meshes, btHeightfieldTerrainShape for
// heightfields (cells split along the (col, row)-(col + 1, row + 1) diagonal,
// as gridTriangles() draws them). No Bullet type appears in this header.
//
// A hit reports the point, the distance along the ray, the terrain friction
// and the unit geometric normal of the triangle hit, pointing up (n.z > 0);
// a vertical face's normal points back towards the ray origin. Rays are cut
// to kMaxRayLength. Queries are deterministic, allocate nothing, and may run
// concurrently on one terrain (they only read it). Edges: a ray through a
// triangle edge hits (1e-9 barycentric tolerance), but Bullet's heightfield
// walk gives the far edges of the grid (last row, last column) to no cell,
// so a vertical ray exactly on them may miss.
#pragma once

#include <memory>
#include <string>

#include "terrain/terrain.h"
#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

constexpr double kMaxRayLength = 1.0e5;  // m

// PlaneTerrain for a plane, the Bullet terrains for a mesh or a heightfield;
// std::invalid_argument if the data are inconsistent (see checkTerrainData).
std::unique_ptr<Terrain> makeTerrain(const TerrainData& data);

// The Bullet version this was built with ("3.24"), for `bdfcar version`.
std::string bulletVersion();

}  // namespace bdfcar::terrain
