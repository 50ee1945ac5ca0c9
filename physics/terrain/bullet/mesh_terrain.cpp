// Triangle-mesh terrain: Bullet's bounding-volume tree, queried shape-level
// (no collision world, no broadphase, nothing allocated per ray).
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>

#include <cmath>
#include <vector>

#include "terrain/bullet/bullet_shapes.h"
#include "terrain/bullet/ray_segment.h"

namespace bdfcar::terrain {

namespace {

class MeshTerrain final : public Terrain {
 public:
  explicit MeshTerrain(const TerrainData& data);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;
  bool surfacesLevelOver(const LevelQuery& q) const override;

 private:
  // Bullet keeps pointers into these two arrays: they outlive the shapes below.
  std::vector<btScalar> coordinates_;  // x, y, z per vertex
  std::vector<int> indices_;           // 3 per triangle
  std::unique_ptr<btTriangleIndexVertexArray> arrays_;
  std::unique_ptr<btBvhTriangleMeshShape> shape_;
  double friction_;
};

// Copies the mesh into Bullet's layout and builds the quantized tree once.
MeshTerrain::MeshTerrain(const TerrainData& data) : friction_(data.friction) {
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
  return castThroughShape(from, direction, maxDistance, Eigen::Vector3d::Zero(), friction_,
                          [this](NearestTriangleHit& nearest, const btVector3& a, const btVector3& b) {
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
std::unique_ptr<Terrain> makeMeshTerrain(const TerrainData& data) { return std::make_unique<MeshTerrain>(data); }

}  // namespace bdfcar::terrain
