// A Wavefront OBJ mesh as plain triangles grouped by material name (usemtl).
// Only what a car body needs: v, vn, f (any index form, polygons fanned), usemtl.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace bdfcar::render {

struct ObjPart {
  std::string material;                   // usemtl name ("" before the first usemtl)
  std::vector<Eigen::Vector3f> corners;   // 3 per triangle, counter-clockwise
  std::vector<Eigen::Vector3f> normals;   // per corner; empty if the file gives none (flat shading)
};

struct ObjMesh {
  std::vector<ObjPart> parts;
  Eigen::Vector3f lo = Eigen::Vector3f::Zero(), hi = Eigen::Vector3f::Zero();  // bounding box
  std::size_t triangles() const;
};

// Parses an OBJ file; throws RenderError naming the file and line on malformed input.
ObjMesh loadObj(const std::string& path);

}  // namespace bdfcar::render
