// Triangles of a terrain asset for drawing: the renderer shows exactly the
// surface the physics queries (a plane becomes a large square around a centre).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;      // world, m
  std::vector<Eigen::Vector3d> normals;       // per vertex, unit
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from above
};

// planeHalfSize: half the side of the square drawn for an infinite plane, m.
TriangleMesh triangulate(const TerrainData& data, double planeHalfSize = 2000.0);

}  // namespace bdfcar::terrain
