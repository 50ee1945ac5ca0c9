#include "render/obj_mesh.h"

#include <optional>
#include <sstream>

#include "config/line_reader.h"
#include "render/frame.h"

namespace bdfcar::render {
namespace {

struct Corner {
  int v = -1, n = -1;
};

// Resolves a 1-based (or negative, relative) OBJ index against `count` items.
int resolveIndex(int index, std::size_t count) {
  const int i = index > 0 ? index - 1 : static_cast<int>(count) + index;
  return (index == 0 || i < 0 || i >= static_cast<int>(count)) ? -1 : i;
}

// Parses "v", "v/t", "v//n" or "v/t/n" into vertex and normal indices.
Corner parseCorner(const std::string& token, std::size_t nv, std::size_t nn) {
  Corner c;
  const std::size_t s1 = token.find('/');
  c.v = resolveIndex(std::stoi(token.substr(0, s1)), nv);
  if (s1 != std::string::npos) {
    const std::size_t s2 = token.find('/', s1 + 1);
    if (s2 != std::string::npos && s2 + 1 < token.size()) c.n = resolveIndex(std::stoi(token.substr(s2 + 1)), nn);
  }
  return c;
}

}  // namespace

std::size_t ObjMesh::triangles() const {
  std::size_t n = 0;
  for (const ObjPart& p : parts) n += p.corners.size() / 3;
  return n;
}

// Reads the file line by line, fanning each face into triangles of the current material's part.
ObjMesh loadObj(const std::string& path) {
  std::optional<config::LineReader> in;
  try {
    in.emplace(path, "OBJ file", config::kObjLines);
  } catch (const std::runtime_error& e) {
    throw RenderError(e.what());
  }
  std::vector<Eigen::Vector3f> positions, normals;
  ObjMesh mesh;
  ObjPart* part = nullptr;
  std::size_t triangles = 0;
  std::string line;
  for (;;) {
    try {
      if (!in->next(line)) break;
    } catch (const std::runtime_error& e) {  // a limit of config::LineReader
      throw RenderError(e.what());
    }
    const long lineNo = in->lineNumber();
    std::istringstream ls(line);
    std::string key;
    if (!(ls >> key) || key[0] == '#') continue;
    try {
      if (key == "v" || key == "vn") {
        Eigen::Vector3f p;
        if (!(ls >> p.x() >> p.y() >> p.z())) throw RenderError("expected three numbers");
        (key == "v" ? positions : normals).push_back(p);
      } else if (key == "usemtl") {
        std::string name;
        ls >> name;
        mesh.parts.push_back({name, {}, {}});
        part = &mesh.parts.back();
      } else if (key == "f") {
        if (!part) {
          mesh.parts.push_back({});
          part = &mesh.parts.back();
        }
        std::vector<Corner> face;
        for (std::string tok; ls >> tok;) face.push_back(parseCorner(tok, positions.size(), normals.size()));
        if (face.size() < 3) throw RenderError("face with fewer than 3 corners");
        for (const Corner& c : face)
          if (c.v < 0) throw RenderError("vertex index out of range");
        triangles += face.size() - 2;
        if (triangles > config::kMaxObjTriangles)
          throw RenderError("more than " + std::to_string(config::kMaxObjTriangles) +
                            " triangles (the limit for an OBJ file)");
        for (std::size_t k = 1; k + 1 < face.size(); ++k)
          for (const Corner& c : {face[0], face[k], face[k + 1]}) {
            part->corners.push_back(positions[c.v]);
            if (c.n >= 0) part->normals.push_back(normals[c.n].normalized());
          }
        if (!part->normals.empty() && part->normals.size() != part->corners.size())
          throw RenderError("faces of one material mix corners with and without normals");
      }
    } catch (const std::logic_error& e) {  // std::stoi on a malformed index
      throw RenderError(path + ":" + std::to_string(lineNo) + ": malformed index (" + e.what() + ")");
    } catch (const RenderError& e) {
      throw RenderError(path + ":" + std::to_string(lineNo) + ": " + e.what());
    }
  }
  if (mesh.triangles() == 0) throw RenderError("OBJ file " + path + " has no faces");
  mesh.lo = mesh.hi = mesh.parts.front().corners.empty() ? positions.front() : mesh.parts.front().corners.front();
  for (const Eigen::Vector3f& p : positions) {
    mesh.lo = mesh.lo.cwiseMin(p);
    mesh.hi = mesh.hi.cwiseMax(p);
  }
  return mesh;
}

}  // namespace bdfcar::render
