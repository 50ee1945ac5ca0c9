// Consistency of TerrainData, checked once before anything builds on it.
#include <cmath>
#include <stdexcept>
#include <string>

#include "terrain/terrain_data.h"
#include "portable_math.h"

namespace bdfcar::terrain {

namespace {

[[noreturn]] void reject(const TerrainData& data, const std::string& problem) {
  const std::string where = data.sourceFile.empty() ? std::string("terrain data") : data.sourceFile;
  throw std::invalid_argument(where + ": " + problem);
}

void checkMesh(const TerrainData& data) {
  if (data.vertices.empty() || data.triangles.empty()) reject(data, "mesh has no triangles");
  for (const Eigen::Vector3d& v : data.vertices)
    if (!v.allFinite()) reject(data, "mesh vertex is not finite");
  const int n = static_cast<int>(data.vertices.size());
  for (const auto& t : data.triangles)
    for (int i : t)
      if (i < 0 || i >= n) reject(data, "triangle index " + std::to_string(i) + " out of range [0, " + std::to_string(n) + ")");
}

void checkHeightfield(const TerrainData& data) {
  if (data.rows < 2 || data.cols < 2) reject(data, "heightfield needs at least 2 x 2 points");
  if (data.heights.size() != static_cast<std::size_t>(data.rows) * static_cast<std::size_t>(data.cols))
    reject(data, "heightfield has " + std::to_string(data.heights.size()) + " heights, expected rows * cols");
  if (!(data.dx > 0 && data.dy > 0 && std::isfinite(data.dx) && std::isfinite(data.dy)))
    reject(data, "heightfield spacing must be positive");
  if (!std::isfinite(data.x0) || !std::isfinite(data.y0)) reject(data, "heightfield origin is not finite");
  for (double h : data.heights)
    if (!std::isfinite(h)) reject(data, "heightfield height is not finite");
}

void checkGround(const TerrainData& data) {
  if (!data.planePoint.allFinite() || !data.planeNormal.allFinite() || data.planeNormal.norm() == 0.0)
    reject(data, "ground needs a finite plane point and a non-zero normal");
  for (const GroundPiece& p : data.pieces) {
    if (!p.at.allFinite() || !std::isfinite(p.heading)) reject(data, "piece '" + p.name + "' is not placed at a finite point");
    if (p.terrain.kind == TerrainKind::Plane || p.terrain.kind == TerrainKind::Ground)
      reject(data, "piece '" + p.name + "' must be a mesh, a heightfield, a road or a track");
    checkTerrainData(p.terrain);
  }
}

}  // namespace

HeadingTurn HeadingTurn::of(double heading) { return {pm::cos(heading), pm::sin(heading)}; }

Eigen::Vector3d GroundPiece::directionToWorld(const Eigen::Vector3d& v) const { return HeadingTurn::of(heading).toWorld(v); }
Eigen::Vector3d GroundPiece::directionToLocal(const Eigen::Vector3d& v) const { return HeadingTurn::of(heading).toLocal(v); }
Eigen::Vector3d GroundPiece::toWorld(const Eigen::Vector3d& local) const { return directionToWorld(local) + at; }
Eigen::Vector3d GroundPiece::toLocal(const Eigen::Vector3d& world) const { return directionToLocal(world - at); }

// The terrain's own centre line, or that of its piece of this name, in world coordinates.
bool findCentreLine(const TerrainData& data, const std::string& name, WorldCentreLine& out) {
  if (data.name == name && !data.centreLine.empty()) {
    out = {data.centreLine, data.centreLineClosed, data.centreLineWidth};
    return true;
  }
  for (const GroundPiece& p : data.pieces) {
    if (p.name != name || p.terrain.centreLine.empty()) continue;
    out.points.clear();
    for (const Eigen::Vector2d& q : p.terrain.centreLine) out.points.push_back(p.toWorld({q.x(), q.y(), 0}).head<2>());
    out.closed = p.terrain.centreLineClosed;
    out.width = p.terrain.centreLineWidth;
    return true;
  }
  return false;
}

// Throws unless the data of the declared kind are complete and finite.
void checkTerrainData(const TerrainData& data) {
  if (!(data.friction > 0) || !std::isfinite(data.friction)) reject(data, "friction must be positive");
  for (const FrictionPatch& f : data.frictionPatches)
    if (!(f.friction > 0) || !std::isfinite(f.friction) || !(f.xMax > f.xMin) || !(f.yMax > f.yMin))
      reject(data, "a friction patch needs a positive friction and x_max > x_min, y_max > y_min");
  switch (data.kind) {
    case TerrainKind::Plane:
      if (!data.planePoint.allFinite() || !data.planeNormal.allFinite() || data.planeNormal.norm() == 0.0)
        reject(data, "plane needs a finite point and a non-zero normal");
      return;
    case TerrainKind::Mesh:
      if (!data.triangleMaterials.empty() && data.triangleMaterials.size() != data.triangles.size())
        reject(data, "mesh has " + std::to_string(data.triangleMaterials.size()) + " triangle materials, expected one per triangle");
      return checkMesh(data);
    case TerrainKind::Ground: return checkGround(data);
    case TerrainKind::Heightfield: return checkHeightfield(data);
  }
  reject(data, "unknown terrain kind");
}

}  // namespace bdfcar::terrain
