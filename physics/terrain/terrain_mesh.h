// Triangles of a terrain asset for drawing: the renderer shows exactly the
// surface the physics queries (a plane becomes a large square around a centre).
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <vector>

#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;      // world, m
  std::vector<Eigen::Vector3d> normals;       // per vertex, unit
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from above
  std::vector<Material> materials;            // one per triangle
  // Triangles from this index on lie beneath the surface (a ground's beds
  // under its pieces): seen only through slits a coarser drawing of the
  // surface leaves, so drawn after it (an early depth test then skips them).
  std::size_t firstBeneath = std::numeric_limits<std::size_t>::max();
};

// Vertices with per-vertex normals for drawing: meshes keep their triangles
// (turned to face up), heightfields become their grid triangles (split as
// Bullet splits them), a plane becomes a square of half side planeHalfSize (m)
// centred on its point, a ground its plane's square and every piece placed
// in the world. Each triangle carries its material. Vertices are split where faces meet at more than
// creaseAngle (rad) so curbs and lips stay sharp while slopes stay smooth.
TriangleMesh triangulate(const TerrainData& data, double planeHalfSize = 2000.0, double creaseAngle = 0.5);

// Triangles of a cols x rows grid of vertices (index row * cols + col), each
// cell split along its (col, row)-(col + 1, row + 1) diagonal, the split
// Bullet's heightfield uses with flipQuadEdges; counter-clockwise seen from
// above; zero-area triangles (cells collapsed by doubled grid lines) dropped.
std::vector<std::array<int, 3>> gridTriangles(int cols, int rows, const std::vector<Eigen::Vector3d>& vertices);

// The same surface as a heightfield, as mesh data (kind = Mesh).
TerrainData heightfieldAsMesh(const TerrainData& heightfield);

}  // namespace bdfcar::terrain
