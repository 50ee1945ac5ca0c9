// Triangle-mesh terrain: Bullet's bounding-volume tree, queried shape-level
// (no collision world, no broadphase, nothing allocated per ray).
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>

#include <vector>

#include "terrain/bullet/bullet_shapes.h"
#include "terrain/bullet/ray_segment.h"

namespace bdfcar::terrain {

namespace {

class MeshTerrain final : public Terrain {
 public:
  explicit MeshTerrain(const TerrainData& data);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;

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

}  // namespace

// The tree over checked mesh data.
std::unique_ptr<Terrain> makeMeshTerrain(const TerrainData& data) { return std::make_unique<MeshTerrain>(data); }

}  // namespace bdfcar::terrain
