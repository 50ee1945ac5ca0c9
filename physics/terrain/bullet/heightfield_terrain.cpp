// Heightfield terrain: Bullet's grid walk over the cells under the ray.
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>

#include <algorithm>
#include <vector>

#include "terrain/bullet/bullet_shapes.h"
#include "terrain/bullet/ray_segment.h"

namespace bdfcar::terrain {

namespace {

class HeightfieldTerrain final : public Terrain {
 public:
  explicit HeightfieldTerrain(const TerrainData& data);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;

 private:
  std::vector<btScalar> heights_;  // Bullet reads these in place: they outlive the shape
  std::unique_ptr<btHeightfieldTerrainShape> shape_;
  // Bullet centres the grid on its bounding box: the world position of that
  // centre, subtracted from rays going in (a pure translation, so hit
  // fractions and normals carry over unchanged).
  Eigen::Vector3d centre_;
  double friction_;
};

// z up (axis 2), cells dx by dy by local scaling, diagonals (col, row)-(col + 1, row + 1)
// (flipQuadEdges, as gridTriangles() splits them); no chunk accelerator, whose
// height culling in Bullet 3.24 reads the y axis as up.
HeightfieldTerrain::HeightfieldTerrain(const TerrainData& data)
    : heights_(data.heights.begin(), data.heights.end()), friction_(data.friction) {
  const auto [lowest, highest] = std::minmax_element(heights_.begin(), heights_.end());
  shape_ = std::make_unique<btHeightfieldTerrainShape>(data.cols, data.rows, heights_.data(), *lowest, *highest,
                                                       /*upAxis=*/2, /*flipQuadEdges=*/true);
  shape_->setLocalScaling(btVector3(data.dx, data.dy, 1.0));
  centre_ = Eigen::Vector3d(data.x0 + 0.5 * (data.cols - 1) * data.dx, data.y0 + 0.5 * (data.rows - 1) * data.dy,
                            0.5 * (*lowest + *highest));
}

// Nearest triangle among the cells the ray's ground track crosses.
Hit HeightfieldTerrain::castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const {
  return castThroughShape(from, direction, maxDistance, centre_, friction_,
                          [this](NearestTriangleHit& nearest, const btVector3& a, const btVector3& b) {
                            shape_->performRaycast(&nearest, a, b);
                          });
}

}  // namespace

// The shape over checked heightfield data.
std::unique_ptr<Terrain> makeHeightfieldTerrain(const TerrainData& data) {
  return std::make_unique<HeightfieldTerrain>(data);
}

}  // namespace bdfcar::terrain
