// The box around a terrain's surface in its own frame: a heightfield's grid
// with its lowest and highest heights, a mesh's vertices. A ground piece's
// footprint is its x and y (ground_terrain.cpp, terrain_mesh.cpp).
#pragma once

#include <Eigen/Core>

#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

struct Extent {
  Eigen::Vector3d lo, hi;  // m; lo = +inf, hi = -inf for a mesh without vertices
};
Extent surfaceExtent(const TerrainData& d);

}  // namespace bdfcar::terrain
