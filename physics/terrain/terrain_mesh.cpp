// Drawable triangles of a terrain: the very surface the ray queries see.
#include "terrain/terrain_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include "portable_math.h"
#include "terrain/terrain_extent.h"

namespace bdfcar::terrain {

namespace {

using Eigen::Vector3d;
using Triangles = std::vector<std::array<int, 3>>;

// Grid points of a heightfield, index row * cols + col.
std::vector<Vector3d> heightfieldVertices(const TerrainData& hf) {
  std::vector<Vector3d> v;
  v.reserve(hf.heights.size());
  for (int row = 0; row < hf.rows; ++row)
    for (int col = 0; col < hf.cols; ++col)
      v.emplace_back(hf.x0 + col * hf.dx, hf.y0 + row * hf.dy, hf.heights[static_cast<std::size_t>(row) * hf.cols + col]);
  return v;
}

// Twice the area times the unit normal of a triangle (right-hand rule).
Vector3d areaNormal(const std::vector<Vector3d>& v, const std::array<int, 3>& t) {
  return (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);
}

// Per-corner normals averaged (area-weighted) over the faces around a vertex
// that meet the corner's face within the crease angle; equal corner normals
// at a vertex share one output vertex. Zero-area triangles are dropped.
TriangleMesh withCreaseNormals(const std::vector<Vector3d>& vertices, const Triangles& triangles,
                               const std::vector<Material>& materials, double creaseAngle) {
  Triangles tris;
  std::vector<Material> kept;
  std::vector<Vector3d> area, unit;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const auto& t = triangles[k];
    const Vector3d n = areaNormal(vertices, t);
    if (n.squaredNorm() == 0.0) continue;
    tris.push_back(t);
    kept.push_back(materials[k]);
    area.push_back(n);
    unit.push_back(n.normalized());
  }
  // Faces around each vertex, compressed rows: faces[first[v] .. first[v + 1]).
  const std::size_t nv = vertices.size();
  std::vector<std::size_t> first(nv + 1, 0);
  for (const auto& t : tris)
    for (int i : t) ++first[i + 1];
  for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<int> faces(first[nv]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for (std::size_t f = 0; f < tris.size(); ++f)
    for (int i : tris[f]) faces[fill[i]++] = static_cast<int>(f);

  const double cosCrease = pm::cos(creaseAngle);
  TriangleMesh out;
  out.triangles = tris;
  out.materials = std::move(kept);
  for (std::size_t v = 0; v < nv; ++v) {
    const std::size_t begin = first[v], end = first[v + 1], firstOut = out.vertices.size();
    for (std::size_t a = begin; a < end; ++a) {
      const int f = faces[a];
      Vector3d sum = Vector3d::Zero();
      for (std::size_t b = begin; b < end; ++b)
        if (unit[faces[b]].dot(unit[f]) >= cosCrease) sum += area[faces[b]];
      const Vector3d n = sum.normalized();
      std::size_t index = firstOut;
      while (index < out.vertices.size() && out.normals[index] != n) ++index;
      if (index == out.vertices.size()) {
        out.vertices.push_back(vertices[v]);
        out.normals.push_back(n);
      }
      for (int k = 0; k < 3; ++k)
        if (tris[f][k] == static_cast<int>(v)) out.triangles[f][k] = static_cast<int>(index);
    }
  }
  return out;
}

// A square of half side h centred on the plane's point, counter-clockwise about its normal.
TriangleMesh planeSquare(const TerrainData& data, double h) {
  const Vector3d n = data.planeNormal.normalized();
  const Vector3d helper = std::abs(n.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  const Vector3d along2 = n.cross(helper).normalized();
  const Vector3d along1 = along2.cross(n);
  const Vector3d& p = data.planePoint;
  TriangleMesh m;
  m.vertices = {p - h * along1 - h * along2, p + h * along1 - h * along2, p + h * along1 + h * along2,
                p - h * along1 + h * along2};
  m.normals.assign(4, n);
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.materials.assign(2, data.material);
  return m;
}

// Each triangle's material: its own where the mesh lists them, else the
// terrain's, except that a marked road's asphalt (its lanes and shoulders)
// is the surface's own triangles there, relief and all: a ribbon laid over
// relief would cut through its crests and sink under its dips. Walls (faces
// steeper than 45 deg: a curb's, a kerb's) stay the terrain's.
std::vector<Material> materialsOf(const TerrainData& data, const std::vector<Vector3d>& v, const Triangles& tris) {
  if (data.triangleMaterials.size() == tris.size()) return data.triangleMaterials;
  std::vector<Material> out(tris.size(), data.material);
  const RoadMarkings& road = data.road;
  if (!road.present) return out;
  const double half = road.asphaltHalfWidth();
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const Vector3d centre = (v[tris[k][0]] + v[tris[k][1]] + v[tris[k][2]]) / 3.0;
    const Vector3d n = areaNormal(v, tris[k]);
    const bool onRoad = centre.x() >= road.startX && centre.x() <= road.endX && std::abs(centre.y() - road.centreY) <= half;
    if (onRoad && std::abs(n.z()) >= std::sqrt(0.5) * n.norm()) out[k] = Material::Asphalt;
  }
  return out;
}

// A convex polygon in the xy plane, counter-clockwise.
using Polygon = std::vector<Eigen::Vector2d>;

// Twice the signed area of a polygon (positive counter-clockwise).
double twiceArea(const Polygon& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d &a = p[i], &b = p[(i + 1) % p.size()];
    s += a.x() * b.y() - b.x() * a.y();
  }
  return s;
}

// The part of p left of the line a -> b (Sutherland-Hodgman, one edge).
Polygon keepLeftOf(const Polygon& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  auto side = [&](const Eigen::Vector2d& x) { return (b.x() - a.x()) * (x.y() - a.y()) - (b.y() - a.y()) * (x.x() - a.x()); };
  Polygon out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d &u = p[i], &w = p[(i + 1) % p.size()];
    const double su = side(u), sw = side(w);
    if (su >= 0) out.push_back(u);
    if ((su >= 0) != (sw >= 0)) out.push_back(u + (w - u) * (su / (su - sw)));
  }
  return out;
}

// Convex p less convex r: the part of p outside r's first edge, then the part
// inside that edge but outside the second, and so on (disjoint convex parts).
std::vector<Polygon> subtract(const Polygon& p, const Polygon& r) {
  std::vector<Polygon> parts;
  Polygon rest = p;
  for (std::size_t i = 0; i < r.size() && rest.size() >= 3; ++i) {
    const Eigen::Vector2d &a = r[i], &b = r[(i + 1) % r.size()];
    const Polygon outside = keepLeftOf(rest, b, a);
    if (outside.size() >= 3 && twiceArea(outside) > 1e-9) parts.push_back(outside);
    rest = keepLeftOf(rest, a, b);
  }
  return parts;
}

// A piece's extent in x and y in its own frame (lo, hi).
std::array<Eigen::Vector2d, 2> footprintBox(const TerrainData& d) {
  const Extent e = surfaceExtent(d);
  return {e.lo.head<2>(), e.hi.head<2>()};
}

// The footprint (its extent in x and y, as ground_terrain.cpp takes it) of a
// piece whose triangles cover all of it: a heightfield, or a mesh whose
// triangles seen from above fill its box once (a generated road's grid).
// Over it the piece is the surface, even where it dips below the plane.
std::optional<Polygon> coveredFootprint(const GroundPiece& p) {
  const TerrainData& d = p.terrain;
  if (d.kind != TerrainKind::Heightfield && d.vertices.empty()) return std::nullopt;
  const auto [lo, hi] = footprintBox(d);
  if (d.kind != TerrainKind::Heightfield) {
    double seen = 0;  // the triangles' areas seen from above
    for (const auto& t : d.triangles) seen += 0.5 * std::abs(areaNormal(d.vertices, t).z());
    const double box = (hi - lo).prod();
    if (!(box > 0) || std::abs(seen - box) > 1e-6 * box) return std::nullopt;
  }
  Polygon corners;
  for (const Eigen::Vector2d& c : {lo, Eigen::Vector2d(hi.x(), lo.y()), hi, Eigen::Vector2d(lo.x(), hi.y())})
    corners.push_back(p.toWorld(Vector3d(c.x(), c.y(), 0.0)).head<2>());
  return corners;
}

// The plane's square without the footprints the pieces cover, as triangle
// fans of convex parts (a plane too steep to be seen from above is kept whole).
TriangleMesh planeAroundPieces(const TerrainData& data, double h) {
  TriangleMesh square = planeSquare(data, h);
  const Vector3d n = data.planeNormal.normalized();
  std::vector<Polygon> cut;
  for (const GroundPiece& p : data.pieces)
    if (const std::optional<Polygon> f = coveredFootprint(p)) cut.push_back(*f);
  if (cut.empty() || n.z() < 0.1) return square;
  std::vector<Polygon> parts{{}};
  for (const Vector3d& v : square.vertices) parts[0].push_back(v.head<2>());
  if (twiceArea(parts[0]) < 0) std::reverse(parts[0].begin(), parts[0].end());
  for (const Polygon& r : cut) {
    std::vector<Polygon> next;
    for (const Polygon& part : parts)
      for (Polygon& piece : subtract(part, r)) next.push_back(std::move(piece));
    parts = std::move(next);
  }
  const Vector3d& c = data.planePoint;
  auto onPlane = [&](const Eigen::Vector2d& q) {
    return Vector3d(q.x(), q.y(), c.z() - (n.x() * (q.x() - c.x()) + n.y() * (q.y() - c.y())) / n.z());
  };
  TriangleMesh out;
  for (const Polygon& part : parts) {
    const int first = static_cast<int>(out.vertices.size());
    for (const Eigen::Vector2d& q : part) {
      out.vertices.push_back(onPlane(q));
      out.normals.push_back(n);
    }
    for (int k = 1; k + 1 < static_cast<int>(part.size()); ++k) {
      out.triangles.push_back({first, first + k, first + k + 1});
      out.materials.push_back(data.material);
    }
  }
  return out;
}

// Appends the rectangle lo..hi of the piece's frame at height z, facing up.
void addRectangle(TriangleMesh& out, const GroundPiece& p, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                  double z, Material material) {
  const int first = static_cast<int>(out.vertices.size());
  for (const Eigen::Vector2d& c : {lo, Eigen::Vector2d(hi.x(), lo.y()), hi, Eigen::Vector2d(lo.x(), hi.y())}) {
    out.vertices.push_back(p.toWorld(Vector3d(c.x(), c.y(), z)));
    out.normals.push_back(p.directionToWorld(Vector3d::UnitZ()));
  }
  out.triangles.push_back({first, first + 1, first + 2});
  out.triangles.push_back({first, first + 2, first + 3});
  out.materials.insert(out.materials.end(), 2, material);
}

// Under a covered footprint, where the plane is cut away, a bed 5 cm below
// the piece's lowest point in its colour (and the road's asphalt under its
// lanes): never seen through the surface itself, it fills the slits that
// coarser drawings of the piece's parts (render/terrain_lod.h) leave between
// them, which would otherwise show the sky.
void addBed(TriangleMesh& out, const GroundPiece& p) {
  const TerrainData& d = p.terrain;
  const double z = surfaceExtent(d).lo.z() - 0.05;
  const auto [lo, hi] = footprintBox(d);
  // A metre beyond the footprint, under the plane: where the piece's edge
  // dips below the plane the riser between them shows the bed, not the sky.
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(1.0);
  addRectangle(out, p, lo - margin, hi + margin, z, d.material);
  if (!d.road.present) return;
  const double half = d.road.asphaltHalfWidth();
  const Eigen::Vector2d roadLo(std::max(lo.x(), d.road.startX), std::max(lo.y(), d.road.centreY - half));
  const Eigen::Vector2d roadHi(std::min(hi.x(), d.road.endX), std::min(hi.y(), d.road.centreY + half));
  // 5 mm above the rest of the bed, so the two need no polygon offset to part.
  if ((roadHi.array() > roadLo.array()).all()) addRectangle(out, p, roadLo, roadHi, z + 0.005, Material::Asphalt);
}

// The ground's plane (where no piece covers it), each piece's triangles
// moved into the world, then the beds under the pieces that cover their
// footprints.
TriangleMesh groundMesh(const TerrainData& data, double planeHalfSize, double creaseAngle) {
  TriangleMesh out = planeAroundPieces(data, planeHalfSize);
  for (const GroundPiece& p : data.pieces) {
    const TriangleMesh piece = triangulate(p.terrain, planeHalfSize, creaseAngle);
    const int first = static_cast<int>(out.vertices.size());
    for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
      out.vertices.push_back(p.toWorld(piece.vertices[v]));
      out.normals.push_back(p.directionToWorld(piece.normals[v]));
    }
    for (const auto& t : piece.triangles) out.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
    out.materials.insert(out.materials.end(), piece.materials.begin(), piece.materials.end());
  }
  out.firstBeneath = out.triangles.size();
  for (const GroundPiece& p : data.pieces)
    if (coveredFootprint(p)) addBed(out, p);
  return out;
}

}  // namespace

// Two triangles per grid cell sharing the (col, row)-(col + 1, row + 1) diagonal.
std::vector<std::array<int, 3>> gridTriangles(int cols, int rows, const std::vector<Vector3d>& vertices) {
  Triangles out;
  out.reserve(2 * static_cast<std::size_t>(std::max(cols - 1, 0)) * std::max(rows - 1, 0));
  for (int row = 0; row + 1 < rows; ++row)
    for (int col = 0; col + 1 < cols; ++col) {
      const int a = row * cols + col, b = a + 1, c = a + cols + 1, d = a + cols;
      for (const std::array<int, 3>& t : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}})
        if (areaNormal(vertices, t).squaredNorm() > 0.0) out.push_back(t);
    }
  return out;
}

// Heightfield grid points and grid triangles as mesh data.
TerrainData heightfieldAsMesh(const TerrainData& heightfield) {
  checkTerrainData(heightfield);
  TerrainData mesh = heightfield;
  mesh.kind = TerrainKind::Mesh;
  mesh.vertices = heightfieldVertices(heightfield);
  mesh.triangles = gridTriangles(heightfield.cols, heightfield.rows, mesh.vertices);
  mesh.rows = mesh.cols = 0;
  mesh.heights.clear();
  return mesh;
}

// Drawable triangles with normals for any kind of terrain.
TriangleMesh triangulate(const TerrainData& data, double planeHalfSize, double creaseAngle) {
  checkTerrainData(data);
  switch (data.kind) {
    case TerrainKind::Plane: return planeSquare(data, planeHalfSize);
    case TerrainKind::Ground: return groundMesh(data, planeHalfSize, creaseAngle);
    case TerrainKind::Heightfield: {
      const std::vector<Vector3d> v = heightfieldVertices(data);
      const Triangles grid = gridTriangles(data.cols, data.rows, v);
      return withCreaseNormals(v, grid, materialsOf(data, v, grid), creaseAngle);
    }
    case TerrainKind::Mesh: break;
  }
  // Mesh files may wind either way: turn every triangle to face up, as the
  // ray queries report it (vertical faces keep their winding).
  Triangles up = data.triangles;
  for (auto& t : up)
    if (areaNormal(data.vertices, t).z() < 0.0) std::swap(t[1], t[2]);
  return withCreaseNormals(data.vertices, up, materialsOf(data, data.vertices, up), creaseAngle);
}

}  // namespace bdfcar::terrain
