// Triangle-mesh terrain: Bullet's bounding-volume tree, queried shape-level
// (no collision world, no broadphase, nothing allocated per ray). Rays
// straight down, what every tyre casts every step, go through a grid over
// the mesh's plan view instead (PlanGrid below): the same triangle test on
// the triangles under the ray, a few instead of a tree walk.
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "terrain/bullet/bullet_shapes.h"
#include "terrain/bullet/ray_segment.h"

namespace bdfcar::terrain {

namespace {

// The triangles whose plan-view box covers each cell of a uniform grid, in
// triangle order. A ray straight down crosses only triangles whose plan view
// holds its point (to the hit test's edge tolerance, which the boxes are
// grown by), so testing the cell's triangles finds what the tree walk
// finds, with the same test and the same tie rule (NearestTriangleHit: the
// lowest triangle index): the same hit, bit for bit (tests/test_terrain.cpp).
// The cells are as long and as wide as the triangles on average, each axis
// on its own: a road meshed in strips across its width (a washboard's
// ridges, 9 cm by 20 m) gets cells of a strip's width, not square cells as
// wide as the road holding hundreds of strips each. Empty where it would not
// pay: a mesh whose triangles span many cells each (a few large faces,
// slivers at all angles) keeps the tree.
class PlanGrid {
 public:
  explicit PlanGrid(const TerrainData& data) {
    const size_t n = data.triangles.size();
    if (n < 64) return;  // the tree's walk is short
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, lengths = 0, widths = 0;
    for (const auto& t : data.triangles) {
      double lx = INFINITY, ly = INFINITY, hx = -INFINITY, hy = -INFINITY;
      for (int k : t) {
        const Eigen::Vector3d& v = data.vertices[k];
        lx = std::min(lx, v.x()), hx = std::max(hx, v.x()), ly = std::min(ly, v.y()), hy = std::max(hy, v.y());
      }
      x0 = std::min(x0, lx), x1 = std::max(x1, hx), y0 = std::min(y0, ly), y1 = std::max(y1, hy);
      lengths += hx - lx;
      widths += hy - ly;
    }
    // Cells about as long and as wide as the triangles, at most 4097 a side.
    const double extent = std::max(x1 - x0, y1 - y0);
    cellX_ = std::max(lengths / static_cast<double>(n), extent / 4096.0);
    cellY_ = std::max(widths / static_cast<double>(n), extent / 4096.0);
    margin_ = 1e-6 + 1e-6 * extent;  // beyond the edge tolerance's reach (1e-9 of a triangle)
    x0_ = x0 - margin_;
    y0_ = y0 - margin_;
    nx_ = static_cast<int>((x1 - x0 + 2 * margin_) / cellX_) + 1;
    ny_ = static_cast<int>((y1 - y0 + 2 * margin_) / cellY_) + 1;
    if (!(cellX_ > 0 && cellY_ > 0) || static_cast<double>(nx_) * ny_ > kMaxCells) {
      clear();
      return;
    }
    std::vector<int> count(static_cast<size_t>(nx_) * ny_ + 1, 0);
    auto forCells = [&](const std::array<int, 3>& t, auto&& f) {
      double lx = INFINITY, ly = INFINITY, hx = -INFINITY, hy = -INFINITY;
      for (int k : t) {
        const Eigen::Vector3d& v = data.vertices[k];
        lx = std::min(lx, v.x()), hx = std::max(hx, v.x()), ly = std::min(ly, v.y()), hy = std::max(hy, v.y());
      }
      const int i0 = column(lx - margin_), i1 = column(hx + margin_), j0 = row(ly - margin_), j1 = row(hy + margin_);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) f(static_cast<size_t>(j) * nx_ + i);
    };
    size_t entries = 0;
    for (const auto& t : data.triangles) forCells(t, [&](size_t c) { ++count[c + 1], ++entries; });
    if (entries > 16 * n) {
      clear();
      return;
    }
    start_.resize(count.size());
    for (size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    start_ = count;
    triangles_.resize(entries);
    for (size_t k = 0; k < n; ++k) forCells(data.triangles[k], [&](size_t c) { triangles_[count[c]++] = static_cast<int>(k); });
  }
  bool empty() const { return start_.empty(); }
  // The triangles under (x, y) (none outside the grid).
  template <class F>
  void forEachAt(double x, double y, F&& f) const {
    if (!(x >= x0_ && y >= y0_)) return;
    const double i = (x - x0_) / cellX_, j = (y - y0_) / cellY_;
    if (!(i < nx_ && j < ny_)) return;
    const size_t c = static_cast<size_t>(j) * nx_ + static_cast<size_t>(i);
    for (int k = start_[c]; k < start_[c + 1]; ++k) f(triangles_[k]);
  }

 private:
  static constexpr double kMaxCells = 1 << 22;
  int column(double x) const { return std::clamp(static_cast<int>((x - x0_) / cellX_), 0, nx_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>((y - y0_) / cellY_), 0, ny_ - 1); }
  void clear() {
    start_.clear();
    triangles_.clear();
  }
  double x0_ = 0, y0_ = 0, cellX_ = 1, cellY_ = 1, margin_ = 0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> start_, triangles_;
};

class MeshTerrain final : public Terrain {
 public:
  MeshTerrain(const TerrainData& data, bool planGrid);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;
  bool surfacesLevelOver(const LevelQuery& q) const override;
  bool planGrid() const { return !grid_.empty(); }

 private:
  // Bullet keeps pointers into these two arrays: they outlive the shapes below.
  std::vector<btScalar> coordinates_;  // x, y, z per vertex
  std::vector<int> indices_;           // 3 per triangle
  std::unique_ptr<btTriangleIndexVertexArray> arrays_;
  std::unique_ptr<btBvhTriangleMeshShape> shape_;
  PlanGrid grid_;
  double friction_;
};

// Copies the mesh into Bullet's layout and builds the quantized tree once.
MeshTerrain::MeshTerrain(const TerrainData& data, bool planGrid)
    : grid_(planGrid ? data : TerrainData{}), friction_(data.friction) {
  coordinates_.reserve(3 * data.vertices.size());
  for (const Eigen::Vector3d& v : data.vertices) coordinates_.insert(coordinates_.end(), {v.x(), v.y(), v.z()});
  indices_.reserve(3 * data.triangles.size());
  for (const auto& t : data.triangles) indices_.insert(indices_.end(), t.begin(), t.end());
  arrays_ = std::make_unique<btTriangleIndexVertexArray>(
      static_cast<int>(data.triangles.size()), indices_.data(), static_cast<int>(3 * sizeof(int)),
      static_cast<int>(data.vertices.size()), coordinates_.data(), static_cast<int>(3 * sizeof(btScalar)));
  shape_ = std::make_unique<btBvhTriangleMeshShape>(arrays_.get(), /*useQuantizedAabbCompression=*/true);
}

// Nearest triangle along the segment, through the tree.
Hit MeshTerrain::castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const {
  const bool down = direction.x() == 0.0 && direction.y() == 0.0 && direction.z() < 0.0;
  return castThroughShape(from, direction, maxDistance, Eigen::Vector3d::Zero(), friction_,
                          [this, down](NearestTriangleHit& nearest, const btVector3& a, const btVector3& b) {
                            if (down && !grid_.empty()) {
                              grid_.forEachAt(a.x(), a.y(), [&](int k) {
                                const int* t = &indices_[3 * static_cast<size_t>(k)];
                                btVector3 v[3];
                                for (int c = 0; c < 3; ++c)
                                  v[c] = btVector3(coordinates_[3 * t[c]], coordinates_[3 * t[c] + 1], coordinates_[3 * t[c] + 2]);
                                nearest.processTriangle(v, 0, k);
                              });
                              return;
                            }
                            // performRaycast is not const in Bullet 3.24 but only reads the tree
                            // and the arrays, so concurrent queries on one terrain are safe.
                            shape_->performRaycast(&nearest, a, b);
                          });
}

// Every triangle whose box the tree finds overlapping the query's box: level
// when its three corners are within the tolerance (so is every point of it)
// and its normal, as a ray's hit reports it (ray_segment.cpp: the winding's
// cross product, made unit, turned up), is within the slope.
class LevelTriangles final : public btTriangleCallback {
 public:
  explicit LevelTriangles(const Terrain::LevelQuery& q) : q_(q) {}
  void processTriangle(btVector3* t, int, int) override {
    if (!level) return;
    constexpr double kMargin = 1e-9;  // m, for the rays' rounding
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(t[k].z() - q_.height) <= q_.tolerance - kMargin)) {
        level = false;
        return;
      }
    const btVector3 n = (t[1] - t[0]).cross(t[2] - t[0]);
    if (n.length2() == 0.0) return;  // degenerate: never hit by a ray
    const Eigen::Vector3d unit = Eigen::Vector3d(n.x(), n.y(), n.z()).normalized();
    if (!(std::abs(unit.z()) >= q_.minNormalZ)) level = false;
  }
  bool level = true;

 private:
  const Terrain::LevelQuery& q_;
};

bool MeshTerrain::surfacesLevelOver(const LevelQuery& q) const {
  LevelTriangles check(q);
  shape_->processAllTriangles(&check, btVector3(q.lo.x(), q.lo.y(), q.zBottom), btVector3(q.hi.x(), q.hi.y(), q.zTop));
  return check.level;
}

}  // namespace

// The tree over checked mesh data.
bool hasPlanGrid(const Terrain& t) {
  const auto* mesh = dynamic_cast<const MeshTerrain*>(&t);
  return mesh && mesh->planGrid();
}

std::unique_ptr<Terrain> makeMeshTerrain(const TerrainData& data, bool planGrid) {
  return std::make_unique<MeshTerrain>(data, planGrid);
}

}  // namespace bdfcar::terrain
