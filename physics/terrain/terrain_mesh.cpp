// Drawable triangles of a terrain: the very surface the ray queries see.
#include "terrain/terrain_mesh.h"

#include <Eigen/Geometry>
#include <cmath>
#include "portable_math.h"

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

// Each triangle's material: its own where the mesh lists them, else the terrain's.
std::vector<Material> materialsOf(const TerrainData& data, std::size_t triangles) {
  if (data.triangleMaterials.size() == triangles) return data.triangleMaterials;
  return std::vector<Material>(triangles, data.material);
}

// The ground's plane, then each piece's triangles moved into the world.
TriangleMesh groundMesh(const TerrainData& data, double planeHalfSize, double creaseAngle) {
  TriangleMesh out = planeSquare(data, planeHalfSize);
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
      return withCreaseNormals(v, grid, materialsOf(data, grid.size()), creaseAngle);
    }
    case TerrainKind::Mesh: break;
  }
  // Mesh files may wind either way: turn every triangle to face up, as the
  // ray queries report it (vertical faces keep their winding).
  Triangles up = data.triangles;
  for (auto& t : up)
    if (areaNormal(data.vertices, t).z() < 0.0) std::swap(t[1], t[2]);
  return withCreaseNormals(data.vertices, up, materialsOf(data, up.size()), creaseAngle);
}

}  // namespace bdfcar::terrain
