#include "terrain/terrain_extent.h"

#include <algorithm>
#include <limits>

namespace bdfcar::terrain {

Extent surfaceExtent(const TerrainData& d) {
  Extent e{Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()),
           Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity())};
  if (d.kind == TerrainKind::Heightfield) {
    const auto [minH, maxH] = std::minmax_element(d.heights.begin(), d.heights.end());
    e.lo = Eigen::Vector3d(d.x0, d.y0, *minH);
    e.hi = Eigen::Vector3d(d.x0 + (d.cols - 1) * d.dx, d.y0 + (d.rows - 1) * d.dy, *maxH);
    return e;
  }
  for (const Eigen::Vector3d& v : d.vertices) {
    e.lo = e.lo.cwiseMin(v);
    e.hi = e.hi.cwiseMax(v);
  }
  return e;
}

}  // namespace bdfcar::terrain
