// The triangles drawn for a terrain asset: the physics' own triangulation.
#pragma once

#include "terrain/terrain_mesh.h"

namespace bdfcar::render {

// terrain::triangulate(data) once target bdfcar_terrain exists; a flat square
// through the asset's plane until then (a plane asset only).
terrain::TriangleMesh terrainSurface(const terrain::TerrainData& data, double planeHalfSize = 2000.0);

}  // namespace bdfcar::render
