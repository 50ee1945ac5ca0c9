#include "render/surface_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bdfcar::render {

// Buckets the triangles into a square grid over the mesh's xy bounds.
SurfaceSampler::SurfaceSampler(const terrain::TriangleMesh& mesh, int maxCellsPerSide) : mesh_(mesh) {
  if (mesh.vertices.empty() || mesh.triangles.empty()) {
    cells_.resize(1);
    return;
  }
  Eigen::Vector2d lo = mesh.vertices[0].head<2>(), hi = lo;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    lo = lo.cwiseMin(v.head<2>());
    hi = hi.cwiseMax(v.head<2>());
  }
  const double side = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-6});
  cell_ = side / maxCellsPerSide;
  x0_ = lo.x();
  y0_ = lo.y();
  nx_ = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / cell_)));
  ny_ = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / cell_)));
  cells_.resize(static_cast<std::size_t>(nx_) * ny_);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    Eigen::Vector2d a = mesh.vertices[mesh.triangles[t][0]].head<2>(), b = a;
    for (int k = 1; k < 3; ++k) {
      a = a.cwiseMin(mesh.vertices[mesh.triangles[t][k]].head<2>());
      b = b.cwiseMax(mesh.vertices[mesh.triangles[t][k]].head<2>());
    }
    const int i0 = std::clamp(static_cast<int>((a.x() - x0_) / cell_), 0, nx_ - 1);
    const int i1 = std::clamp(static_cast<int>((b.x() - x0_) / cell_), 0, nx_ - 1);
    const int j0 = std::clamp(static_cast<int>((a.y() - y0_) / cell_), 0, ny_ - 1);
    const int j1 = std::clamp(static_cast<int>((b.y() - y0_) / cell_), 0, ny_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) cells_[static_cast<std::size_t>(j) * nx_ + i].push_back(t);
  }
}

// Barycentric interpolation in the triangles of the cell holding (x, y).
std::optional<double> SurfaceSampler::height(double x, double y) const {
  const int i = static_cast<int>(std::floor((x - x0_) / cell_)), j = static_cast<int>(std::floor((y - y0_) / cell_));
  if (i < 0 || j < 0 || i >= nx_ || j >= ny_ || mesh_.triangles.empty()) return std::nullopt;
  double best = -std::numeric_limits<double>::infinity();
  for (int t : cells_[static_cast<std::size_t>(j) * nx_ + i]) {
    const Eigen::Vector3d &a = mesh_.vertices[mesh_.triangles[t][0]], &b = mesh_.vertices[mesh_.triangles[t][1]],
                          &c = mesh_.vertices[mesh_.triangles[t][2]];
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (std::abs(det) < 1e-12) continue;  // vertical triangle: no height to give
    const double u = ((x - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (y - a.y())) / det;
    const double v = ((b.x() - a.x()) * (y - a.y()) - (x - a.x()) * (b.y() - a.y())) / det;
    const double eps = 1e-9;
    if (u < -eps || v < -eps || u + v > 1 + eps) continue;
    best = std::max(best, a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z()));
  }
  if (!std::isfinite(best)) return std::nullopt;
  return best;
}

double SurfaceSampler::heightOr(double x, double y, double fallback) const { return height(x, y).value_or(fallback); }

}  // namespace bdfcar::render
