// A terrain asset as plain data, loaded once from assets/terrain/*.toml and
// shared by the physics (ray queries) and the renderer (the same triangles).
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <string>
#include <vector>

namespace bdfcar::terrain {

enum class TerrainKind { Plane, Mesh, Heightfield };

// Road painting for the renderer (no effect on physics).
struct RoadMarkings {
  bool present = false;
  double startX = -50, endX = 1000;  // road extent along world x, m
  double centreY = 0.0;              // lateral position of the road centre, m
  int lanes = 2;
  double laneWidth = 3.5;            // m
};

// A rectangle of the ground plane (world x, y; unbounded sides allowed) whose
// surface has a friction of its own: a wet or icy lane, grass, gravel.
struct FrictionPatch {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  double xMin = -kInf, xMax = kInf, yMin = -kInf, yMax = kInf;  // m
  double friction = 0.8;
  bool contains(double x, double y) const { return x >= xMin && x < xMax && y >= yMin && y < yMax; }
};

struct TerrainData {
  std::string name;
  std::string sourceFile;            // the .toml it came from
  TerrainKind kind = TerrainKind::Plane;
  double friction = 0.8;
  // Where a ray hits inside a patch, the patch's friction (the last patch
  // listed that contains the hit wins); elsewhere `friction`.
  std::vector<FrictionPatch> frictionPatches;
  // Plane.
  Eigen::Vector3d planePoint = Eigen::Vector3d::Zero();
  Eigen::Vector3d planeNormal = Eigen::Vector3d::UnitZ();
  // Mesh: world coordinates (m, z up) and triangles (counter-clockwise seen from above).
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  // Heightfield: heights[row * cols + col] at (x0 + col * dx, y0 + row * dy).
  int rows = 0, cols = 0;
  double x0 = 0, y0 = 0, dx = 1, dy = 1;
  std::vector<double> heights;
  RoadMarkings road;
};

// Throws std::invalid_argument (naming sourceFile) unless the data describe a
// usable surface: finite numbers, a non-zero plane normal, triangle indices in
// range, a heightfield of at least 2 x 2 points with positive spacing.
void checkTerrainData(const TerrainData& data);

}  // namespace bdfcar::terrain
