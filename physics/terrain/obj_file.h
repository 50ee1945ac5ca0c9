// Wavefront OBJ geometry for terrain meshes: `v x y z` vertices and `f`
// faces (triangles; quads and convex polygons are split into a fan; indices
// may be negative, i.e. relative; `i/t/n` forms accepted). Everything else
// (normals, texture coordinates, groups, materials) is ignored.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace bdfcar::terrain {

struct ObjMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // 0-based
};

// Reads an OBJ file; errors are TerrainFileError with "path:line: ...".
ObjMesh readObj(const std::string& path);

}  // namespace bdfcar::terrain
