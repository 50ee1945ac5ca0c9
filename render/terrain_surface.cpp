#include "render/terrain_surface.h"

#include <Eigen/Geometry>

namespace bdfcar::render {

#if BDFCAR_HAVE_TERRAIN_MESH
// The physics' triangulation: the renderer shows exactly what the tyres touch.
terrain::TriangleMesh terrainSurface(const terrain::TerrainData& data, double planeHalfSize) {
  return terrain::triangulate(data, planeHalfSize);
}
#else
// TERRAIN CALL SITE: bdfcar_terrain (terrain::triangulate) does not exist yet, so
// every asset is drawn as its plane (mesh and heightfield assets included).
// render/CMakeLists.txt switches to the function above as soon as the target exists.
terrain::TriangleMesh terrainSurface(const terrain::TerrainData& data, double planeHalfSize) {
  const Eigen::Vector3d n = data.planeNormal.normalized();
  const Eigen::Vector3d u = (Eigen::Vector3d::UnitX() - n * n.x()).norm() > 1e-6
                                ? (Eigen::Vector3d::UnitX() - n * n.x()).normalized()
                                : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d v = n.cross(u);
  const Eigen::Vector3d& c = data.planePoint;
  terrain::TriangleMesh m;
  for (int k = 0; k < 4; ++k) {
    const double su = (k == 1 || k == 2) ? 1 : -1, sv = (k >= 2) ? 1 : -1;
    m.vertices.push_back(c + planeHalfSize * (su * u + sv * v));
    m.normals.push_back(n);
  }
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.materials.assign(2, data.material);
  return m;
}
#endif

}  // namespace bdfcar::render
