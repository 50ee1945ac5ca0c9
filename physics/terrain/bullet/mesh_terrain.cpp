// Triangle-mesh terrain: Bullet's bounding-volume tree, queried shape-level
// (no collision world, no broadphase, nothing allocated per ray). Rays
// straight down, what every tyre casts every step, go through a grid over
// the mesh's plan view instead (PlanGrid below): the same triangle test on
// the triangles under the ray, a few instead of a tree walk.
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>

#include <algorithm>
#include <array>
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
//
// Of the triangles whose box holds the ray's point, those whose plan view
// it lies clearly outside (PlanEdges) are not tested at all: on a road of
// long slivers the boxes of four or five hold each point, the triangle of
// one or two.
class PlanGrid {
 public:
  explicit PlanGrid(const TerrainData& data) {
    const size_t n = data.triangles.size();
    if (n < 64) return;  // the tree's walk is short
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, lengths = 0, widths = 0;
    boxes_.reserve(n);
    for (const auto& t : data.triangles) {
      Box b{INFINITY, -INFINITY, INFINITY, -INFINITY};
      for (int k : t) {
        const Eigen::Vector3d& v = data.vertices[k];
        b.xLo = std::min(b.xLo, v.x()), b.xHi = std::max(b.xHi, v.x()), b.yLo = std::min(b.yLo, v.y()), b.yHi = std::max(b.yHi, v.y());
      }
      x0 = std::min(x0, b.xLo), x1 = std::max(x1, b.xHi), y0 = std::min(y0, b.yLo), y1 = std::max(y1, b.yHi);
      lengths += b.xHi - b.xLo;
      widths += b.yHi - b.yLo;
      boxes_.push_back(b);
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
    for (Box& b : boxes_) b = {b.xLo - margin_, b.xHi + margin_, b.yLo - margin_, b.yHi + margin_};
    const double reach = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1)});
    edges_.reserve(n);
    for (const auto& t : data.triangles)
      edges_.push_back(PlanEdges::of(data.vertices[t[0]], data.vertices[t[1]], data.vertices[t[2]], reach));
    std::vector<int> count(static_cast<size_t>(nx_) * ny_ + 1, 0);
    auto forCells = [&](size_t k, auto&& f) {
      const Box& b = boxes_[k];
      const int i0 = column(b.xLo), i1 = column(b.xHi), j0 = row(b.yLo), j1 = row(b.yHi);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) f(static_cast<size_t>(j) * nx_ + i);
    };
    size_t entries = 0;
    for (size_t k = 0; k < n; ++k) forCells(k, [&](size_t c) { ++count[c + 1], ++entries; });
    if (entries > 16 * n) {
      clear();
      return;
    }
    start_.resize(count.size());
    for (size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    start_ = count;
    triangles_.resize(entries);
    for (size_t k = 0; k < n; ++k) forCells(k, [&](size_t c) { triangles_[count[c]++] = static_cast<int>(k); });
  }
  bool empty() const { return start_.empty(); }
  // The triangles under (x, y) (none outside the grid): those of its cell
  // whose grown plan-view box holds it (the others' corners need not be
  // fetched nor the hit test run).
  template <class F>
  void forEachAt(double x, double y, F&& f) const {
    if (!(x >= x0_ && y >= y0_)) return;
    const double i = (x - x0_) / cellX_, j = (y - y0_) / cellY_;
    if (!(i < nx_ && j < ny_)) return;
    const size_t c = static_cast<size_t>(j) * nx_ + static_cast<size_t>(i);
    for (int k = start_[c]; k < start_[c + 1]; ++k) {
      const size_t t = static_cast<size_t>(triangles_[k]);
      const Box& b = boxes_[t];
      if (x >= b.xLo && x <= b.xHi && y >= b.yLo && y <= b.yHi && edges_[t].near(x, y)) f(triangles_[k]);
    }
  }
  // The triangles of every cell the plan-view box [lo, hi] touches (a
  // triangle that spans cells comes once per cell): each one under a point
  // of the box among them. Nothing where the box misses the grid.
  template <class F>
  void forEachIn(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, F&& f) const {
    const double xEnd = x0_ + nx_ * cellX_, yEnd = y0_ + ny_ * cellY_;
    if (!(hi.x() >= x0_ && hi.y() >= y0_ && lo.x() < xEnd && lo.y() < yEnd)) return;
    const int i0 = column(lo.x()), i1 = column(hi.x()), j0 = row(lo.y()), j1 = row(hi.y());
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const size_t c = static_cast<size_t>(j) * nx_ + i;
        for (int k = start_[c]; k < start_[c + 1]; ++k) f(triangles_[k]);
      }
  }

 private:
  static constexpr double kMaxCells = 1 << 22;
  int column(double x) const { return std::clamp(static_cast<int>((x - x0_) / cellX_), 0, nx_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>((y - y0_) / cellY_), 0, ny_ - 1); }
  void clear() {
    start_.clear();
    triangles_.clear();
    boxes_.clear();
    edges_.clear();
  }
  struct Box {
    double xLo, xHi, yLo, yHi;
  };
  // A triangle's plan view grown by a margin, as three half-planes: a point
  // with a negative distance to one (n . p + c < 0) is outside it, where the
  // ray's hit test (ray_segment.cpp, in Bullet's single precision) rejects
  // it too. The margin is a hundred times that test's rounding: 1 cm, 1e-5
  // of the grid's largest coordinate (the ray's point and the corners
  // rounded to single precision, the products of the test), 1e-3 of the
  // longest side (the test's determinant on a triangle at least 1e-4 of its
  // longest side squared in area). Thinner in plan view (a sliver, a wall):
  // always tested.
  struct PlanEdges {
    std::array<float, 3> nx{}, ny{}, c{1.0f, 1.0f, 1.0f};
    bool near(double x, double y) const {
      return nx[0] * x + ny[0] * y + c[0] >= 0 && nx[1] * x + ny[1] * y + c[1] >= 0 && nx[2] * x + ny[2] * y + c[2] >= 0;
    }
    static PlanEdges of(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double reach) {
      const std::array<Eigen::Vector2d, 3> v{a.head<2>(), b.head<2>(), c.head<2>()};
      const Eigen::Vector2d e1 = v[1] - v[0], e2 = v[2] - v[0];
      const double area2 = e1.x() * e2.y() - e1.y() * e2.x();  // twice the signed area
      double longest = 0;
      for (int i = 0; i < 3; ++i) longest = std::max(longest, (v[(i + 1) % 3] - v[i]).norm());
      PlanEdges out;
      if (!(std::abs(area2) >= 2e-4 * longest * longest) || !std::isfinite(area2)) return out;  // always tested
      const double margin = 1e-2 + 1e-5 * reach + 1e-3 * longest;
      const double side = area2 > 0 ? 1.0 : -1.0;  // inward is left of each side when counter-clockwise
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector2d d = v[(i + 1) % 3] - v[i];
        const Eigen::Vector2d inward = side * Eigen::Vector2d(-d.y(), d.x()) / d.norm();
        out.nx[i] = static_cast<float>(inward.x());
        out.ny[i] = static_cast<float>(inward.y());
        out.c[i] = static_cast<float>(margin - inward.dot(v[i]));
      }
      return out;
    }
  };
  double x0_ = 0, y0_ = 0, cellX_ = 1, cellY_ = 1, margin_ = 0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> start_, triangles_;
  std::vector<Box> boxes_;  // each triangle's plan view, grown by the margin
  std::vector<PlanEdges> edges_;  // each triangle's plan view, grown by its own margin
};

struct TriangleSpan {
  double zLo = 0, zHi = 0, normalZ = 0;
};
TriangleSpan triangleSpan(const btVector3* t);

class MeshTerrain final : public Terrain {
 public:
  MeshTerrain(const TerrainData& data, bool planGrid);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;
  bool surfacesLevelOver(const LevelQuery& q) const override;
  bool planGrid() const { return !grid_.empty(); }
  // Triangle k's corners, as Bullet's arrays hold them.
  void corners(int k, btVector3* v) const;

 private:
  // Bullet keeps pointers into these two arrays: they outlive the shapes below.
  std::vector<btScalar> coordinates_;  // x, y, z per vertex
  std::vector<int> indices_;           // 3 per triangle
  std::unique_ptr<btTriangleIndexVertexArray> arrays_;
  std::unique_ptr<btBvhTriangleMeshShape> shape_;
  PlanGrid grid_;
  std::vector<TriangleSpan> spans_;  // per triangle, with the grid (surfacesLevelOver)
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
  if (grid_.empty()) return;
  spans_.resize(data.triangles.size());
  btVector3 v[3];
  for (size_t k = 0; k < spans_.size(); ++k) {
    corners(static_cast<int>(k), v);
    spans_[k] = triangleSpan(v);
  }
}

void MeshTerrain::corners(int k, btVector3* v) const {
  const int* t = &indices_[3 * static_cast<size_t>(k)];
  for (int c = 0; c < 3; ++c) v[c] = btVector3(coordinates_[3 * t[c]], coordinates_[3 * t[c] + 1], coordinates_[3 * t[c] + 2]);
}

// Nearest triangle along the segment, through the tree.
Hit MeshTerrain::castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const {
  const bool down = direction.x() == 0.0 && direction.y() == 0.0 && direction.z() < 0.0;
  return castThroughShape(from, direction, maxDistance, Eigen::Vector3d::Zero(), friction_,
                          [this, down](NearestTriangleHit& nearest, const btVector3& a, const btVector3& b) {
                            if (down && !grid_.empty()) {
                              grid_.forEachAt(a.x(), a.y(), [&](int k) {
                                btVector3 v[3];
                                corners(k, v);
                                nearest.processTriangle(v, 0, k);
                              });
                              return;
                            }
                            // performRaycast is not const in Bullet 3.24 but only reads the tree
                            // and the arrays, so concurrent queries on one terrain are safe.
                            shape_->performRaycast(&nearest, a, b);
                          });
}

// What the level check asks of a triangle: its corners' lowest and highest
// z and its normal's |z| as a ray's hit reports it (ray_segment.cpp: the
// winding's cross product, made unit; infinite for a degenerate triangle,
// which no ray hits).
TriangleSpan triangleSpan(const btVector3* t) {
  TriangleSpan s;
  s.zLo = std::min({t[0].z(), t[1].z(), t[2].z()});
  s.zHi = std::max({t[0].z(), t[1].z(), t[2].z()});
  const btVector3 n = (t[1] - t[0]).cross(t[2] - t[0]);
  s.normalZ = n.length2() == 0.0 ? INFINITY : std::abs(Eigen::Vector3d(n.x(), n.y(), n.z()).normalized().z());
  return s;
}

// Level: its three corners within the tolerance (so is every point of it;
// the corners' extremes decide, |z - height| being monotonic on each side)
// and its normal within the slope.
bool levelTriangle(const TriangleSpan& s, const Terrain::LevelQuery& q) {
  constexpr double kMargin = 1e-9;  // m, for the rays' rounding
  const double reach = q.tolerance - kMargin;
  return std::abs(s.zLo - q.height) <= reach && std::abs(s.zHi - q.height) <= reach && s.normalZ >= q.minNormalZ;
}

// Every triangle whose box the tree finds overlapping the query's box.
class LevelTriangles final : public btTriangleCallback {
 public:
  explicit LevelTriangles(const Terrain::LevelQuery& q) : q_(q) {}
  void processTriangle(btVector3* t, int, int) override { level = level && levelTriangle(triangleSpan(t), q_); }
  bool level = true;

 private:
  const Terrain::LevelQuery& q_;
};

// With a plan grid, the triangles of the cells under the box whose heights
// reach into the rays' span: every triangle a ray down through the box can
// meet, for a few cells' worth of work, each from its span kept since the
// start. (Bullet's stackless tree walk costs about the same for a wheel's
// strip as for a car's footprint.)
bool MeshTerrain::surfacesLevelOver(const LevelQuery& q) const {
  if (grid_.empty()) {
    LevelTriangles check(q);
    shape_->processAllTriangles(&check, btVector3(q.lo.x(), q.lo.y(), q.zBottom), btVector3(q.hi.x(), q.hi.y(), q.zTop));
    return check.level;
  }
  bool level = true;
  grid_.forEachIn(q.lo, q.hi, [&](int k) {
    const TriangleSpan& s = spans_[static_cast<size_t>(k)];
    if (s.zHi < q.zBottom || s.zLo > q.zTop) return;  // out of the rays' reach
    level = level && levelTriangle(s, q);
  });
  return level;
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
