// A terrain asset as plain data, loaded once from assets/terrain/*.toml and
// shared by the physics (ray queries) and the renderer (the same triangles).
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <string>
#include <vector>

namespace bdfcar::terrain {

// Ground: a base plane with placed pieces (terrains of the other kinds) on it.
enum class TerrainKind { Plane, Mesh, Heightfield, Ground };

// What a surface is made of, for the renderer (its texture and colour; the
// tyres read only the friction). Paint and the two curb colours come from
// generated tracks (track.h).
enum class Material : unsigned char { Grass, Asphalt, Concrete, Gravel, Paint, CurbRed, CurbWhite };

// Road painting for the renderer (no effect on physics).
struct RoadMarkings {
  bool present = false;
  double startX = -50, endX = 1000;  // road extent along world x, m
  double centreY = 0.0;              // lateral position of the road centre, m
  int lanes = 2;
  double laneWidth = 3.5;            // m
  // Drawn asphalt beyond each edge line, m (not read from files).
  static constexpr double kShoulder = 0.6;
  // Half the drawn asphalt's width: the lanes and a shoulder each side, m.
  double asphaltHalfWidth() const { return 0.5 * lanes * laneWidth + kShoulder; }
};

// A rectangle of the ground plane (world x, y; unbounded sides allowed) whose
// surface has a friction of its own: a wet or icy lane, grass, gravel.
struct FrictionPatch {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  double xMin = -kInf, xMax = kInf, yMin = -kInf, yMax = kInf;  // m
  double friction = 0.8;
  bool contains(double x, double y) const { return x >= xMin && x < xMax && y >= yMin && y < yMax; }
};

struct GroundPiece;

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
  // What the surface is drawn as: `material` everywhere, or for a mesh with
  // triangleMaterials (one per triangle) each triangle's own.
  Material material = Material::Grass;
  std::vector<Material> triangleMaterials;
  // A generated track's centre line (track.h), in this terrain's frame: the
  // path a driver may follow around it; closed if the track is a circuit.
  std::vector<Eigen::Vector2d> centreLine;
  bool centreLineClosed = false;
  double centreLineWidth = 0;  // m, the road's width along it (0: not a road)
  // Ground: the plane (planePoint, planeNormal, friction, frictionPatches,
  // material) with these pieces placed on it.
  std::vector<GroundPiece> pieces;
};

// A turn about z (a heading), its cosine and sine taken once: vectors of the
// turned frame to the unturned one and back. Ground pieces, the ground's
// rays, the planar car's base frame.
struct HeadingTurn {
  double c = 1, s = 0;
  static HeadingTurn of(double heading);
  Eigen::Vector3d toWorld(const Eigen::Vector3d& v) const { return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()}; }
  Eigen::Vector3d toLocal(const Eigen::Vector3d& v) const { return {c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z()}; }
};

// A terrain placed on a ground: world = R_z(heading) local + at. A ray
// reaching both the ground's plane and a piece, or two pieces, at the same
// distance takes the piece listed last (ground_terrain.cpp): a flat piece on
// the plane is what the tyres touch.
struct GroundPiece {
  std::string name;
  TerrainData terrain;  // in its own frame; never a plane or a ground
  Eigen::Vector3d at = Eigen::Vector3d::Zero();  // m
  double heading = 0.0;                          // rad, about world z
  Eigen::Vector3d toWorld(const Eigen::Vector3d& local) const;
  Eigen::Vector3d directionToWorld(const Eigen::Vector3d& local) const;
  Eigen::Vector3d toLocal(const Eigen::Vector3d& world) const;
  Eigen::Vector3d directionToLocal(const Eigen::Vector3d& world) const;
};

// Where a named track piece's centre line lies in the world: the points of
// the piece called `name` (or of the terrain itself, if it is that track),
// or nothing if there is no such track.
struct WorldCentreLine {
  std::vector<Eigen::Vector2d> points;
  bool closed = false;
  double width = 0;  // m, the road's (0: not known)
};
bool findCentreLine(const TerrainData& data, const std::string& name, WorldCentreLine& out);

// Throws std::invalid_argument (naming sourceFile) unless the data describe a
// usable surface: finite numbers, a non-zero plane normal, triangle indices in
// range, a heightfield of at least 2 x 2 points with positive spacing.
void checkTerrainData(const TerrainData& data);

}  // namespace bdfcar::terrain
