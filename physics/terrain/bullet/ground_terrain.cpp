// A ground: its plane and the pieces placed on it, each queried in its own
// frame. The nearest piece hit wins, a tie going to the piece listed last.
// Over a piece's footprint (its extent in x and y, in its own frame) the
// piece is the surface, so it may dip below the plane (a pothole); the plane
// is the surface where no piece is hit, and outside the footprints where it
// is hit first.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "terrain/bullet/bullet_shapes.h"
#include "terrain/bullet/bullet_terrain.h"
#include "terrain/terrain_extent.h"

namespace bdfcar::terrain {

namespace {

// A hit this much nearer than another is nearer; closer than that it is the
// same surface: a flat piece lies on the plane, and Bullet works in single
// precision (a piece a kilometre from its origin rounds to ~0.1 mm).
constexpr double kTie = 1e-3;  // m

struct PlacedPiece {
  GroundPiece placement;  // terrain data dropped: only the transform is used
  std::unique_ptr<Terrain> terrain;
  Eigen::Vector3d lo, hi;  // world bounding box, m
  Eigen::Vector2d footLo, footHi;  // extent in x and y in its own frame, m
  // The heading's turn, once (GroundPiece's transforms take it at every
  // call: four times a ray).
  HeadingTurn turn;
  Eigen::Vector3d directionToLocal(const Eigen::Vector3d& v) const { return turn.toLocal(v); }
  Eigen::Vector3d directionToWorld(const Eigen::Vector3d& v) const { return turn.toWorld(v); }
  Eigen::Vector3d toLocal(const Eigen::Vector3d& world) const { return turn.toLocal(world - placement.at); }
  Eigen::Vector3d toWorld(const Eigen::Vector3d& local) const { return turn.toWorld(local) + placement.at; }
  // Whether the box [lo, hi] meets the piece's world box: compared an axis
  // at a time, most pieces lying beside a ray's box in x or y (Eigen's
  // whole-vector reductions cost a tenth of a ray on a ground of ten pieces).
  bool boxMeets(const Eigen::Vector3d& qlo, const Eigen::Vector3d& qhi) const {
    return !(qhi.x() < lo.x() || qlo.x() > hi.x() || qhi.y() < lo.y() || qlo.y() > hi.y() || qhi.z() < lo.z() ||
             qlo.z() > hi.z());
  }
  bool covers(const Eigen::Vector3d& world) const {
    const Eigen::Vector2d q = toLocal(world).head<2>();
    return (q.array() >= footLo.array()).all() && (q.array() <= footHi.array()).all();
  }
};

// The corners of the box around a piece's surface in its own frame.
std::vector<Eigen::Vector3d> boxCorners(const TerrainData& d) {
  const Extent e = surfaceExtent(d);
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < 8; ++k)
    corners.emplace_back(k & 1 ? e.hi.x() : e.lo.x(), k & 2 ? e.hi.y() : e.lo.y(), k & 4 ? e.hi.z() : e.lo.z());
  return corners;
}

class GroundTerrain final : public Terrain {
 public:
  explicit GroundTerrain(const TerrainData& data);
  Hit castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const override;
  bool levelOver(const LevelQuery& q) const override;

 private:
  std::unique_ptr<Terrain> plane_;
  std::vector<PlacedPiece> pieces_;
};

// The plane with the ground's friction patches; each piece's own terrain
// (its patches in its frame) and the box around its triangles in the world.
GroundTerrain::GroundTerrain(const TerrainData& data) {
  TerrainData plane = data;
  plane.kind = TerrainKind::Plane;
  plane.pieces.clear();
  plane_ = makeTerrain(plane);
  for (const GroundPiece& p : data.pieces) {
    PlacedPiece placed;
    placed.placement = GroundPiece{p.name, TerrainData{}, p.at, p.heading};
    placed.turn = HeadingTurn::of(p.heading);
    placed.terrain = makeTerrain(p.terrain);
    placed.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    placed.hi = -placed.lo;
    placed.footLo = placed.lo.head<2>();
    placed.footHi = placed.hi.head<2>();
    for (const Eigen::Vector3d& v : boxCorners(p.terrain)) {
      placed.footLo = placed.footLo.cwiseMin(v.head<2>());
      placed.footHi = placed.footHi.cwiseMax(v.head<2>());
      const Eigen::Vector3d w = p.toWorld(v);
      placed.lo = placed.lo.cwiseMin(w);
      placed.hi = placed.hi.cwiseMax(w);
    }
    pieces_.push_back(std::move(placed));
  }
}

Hit GroundTerrain::castRay(const Eigen::Vector3d& from, const Eigen::Vector3d& direction, double maxDistance) const {
  const Hit plane = plane_->castRay(from, direction, maxDistance);
  const double n = direction.norm();
  if (!(n > 0) || !std::isfinite(n)) return plane;
  const Eigen::Vector3d to = from + direction / n * std::min(maxDistance, kMaxRayLength);
  const Eigen::Vector3d lo = from.cwiseMin(to), hi = from.cwiseMax(to);
  Hit best;
  for (const PlacedPiece& p : pieces_) {
    if (!p.boxMeets(lo, hi)) continue;
    Hit h = p.terrain->castRay(p.toLocal(from), p.directionToLocal(direction), maxDistance);
    if (!h.hit || (best.hit && h.distance > best.distance + kTie)) continue;
    h.point = p.toWorld(h.point);
    h.normal = p.directionToWorld(h.normal);
    best = h;
  }
  if (!best.hit) return plane;
  if (!plane.hit || plane.distance >= best.distance - kTie) return best;
  for (const PlacedPiece& p : pieces_)
    if (p.covers(plane.point)) return best;
  return plane;
}

// A ray meets the plane or a piece (castRay above): level over the box when
// the plane is, and every piece whose box overlaps the rays' has only level
// surfaces there (asked in its own frame: the query's box turned into it,
// the heights less its own). A piece turns about z only: its normals' z
// are the world's.
bool GroundTerrain::levelOver(const LevelQuery& q) const {
  if (!plane_->levelOver(q)) return false;
  const Eigen::Vector3d lo(q.lo.x(), q.lo.y(), q.zBottom), hi(q.hi.x(), q.hi.y(), q.zTop);
  for (const PlacedPiece& p : pieces_) {
    if (!p.boxMeets(lo, hi)) continue;
    LevelQuery local = q;
    Eigen::Vector2d a = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), b = -a;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d c = p.toLocal(Eigen::Vector3d(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), 0.0));
      a = a.cwiseMin(c.head<2>());
      b = b.cwiseMax(c.head<2>());
    }
    const double dz = p.placement.at.z();
    local.lo = a;
    local.hi = b;
    local.zTop = q.zTop - dz;
    local.zBottom = q.zBottom - dz;
    local.height = q.height - dz;
    if (!p.terrain->surfacesLevelOver(local)) return false;
  }
  return true;
}

}  // namespace

std::unique_ptr<Terrain> makeGroundTerrain(const TerrainData& data) { return std::make_unique<GroundTerrain>(data); }

}  // namespace bdfcar::terrain
