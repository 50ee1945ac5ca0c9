// Height of a triangulated terrain under a point (x, y): places road, cones
// and markings on the surface the physics drives on. Plain Eigen, no OSG.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "terrain/terrain_mesh.h"

namespace bdfcar::render {

class SurfaceSampler {
 public:
  explicit SurfaceSampler(const terrain::TriangleMesh& mesh, int maxCellsPerSide = 256);
  // Highest surface z above (x, y), or nothing outside the mesh.
  std::optional<double> height(double x, double y) const;
  // height(), or `fallback` outside the mesh.
  double heightOr(double x, double y, double fallback) const;

 private:
  const terrain::TriangleMesh& mesh_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;  // triangle indices overlapping each cell (ny x nx)
};

}  // namespace bdfcar::render
