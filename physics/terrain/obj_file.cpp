// A minimal OBJ reader: the vertex and face statements a terrain needs.
#include "terrain/obj_file.h"
#include "config/input_files.h"
#include "config/line_reader.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "terrain/terrain_file.h"

namespace bdfcar::terrain {

namespace {

struct LineContext {
  const std::string& path;
  int line;
};

[[noreturn]] void fail(const LineContext& at, const std::string& message) {
  throw TerrainFileError(at.path + ":" + std::to_string(at.line) + ": " + message);
}

// Coordinates beyond 1000 km are typos, not terrain (as in terrain_file.cpp).
constexpr double kMaxCoordinate = 1e6;  // m

// A whole token as a finite double (std::from_chars: locale-independent).
double parseCoordinate(const LineContext& at, const std::string& token) {
  double x = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
  if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(x))
    fail(at, "expected a finite number, got '" + token + "'");
  if (std::abs(x) > kMaxCoordinate) fail(at, "expected a coordinate in [-1e+06, 1e+06] m, got '" + token + "'");
  return x;
}

// The vertex index of a face corner "i", "i/t", "i//n" or "i/t/n" as 0-based;
// negative indices count back from the last vertex read so far.
int parseCorner(const LineContext& at, const std::string& token, int vertexCount) {
  const std::string index = token.substr(0, token.find('/'));
  long long i = 0;
  const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), i);
  if (ec != std::errc() || end != index.data() + index.size() || i == 0)
    fail(at, "expected a non-zero vertex index, got '" + token + "'");
  const long long zeroBased = i > 0 ? i - 1 : vertexCount + i;
  if (zeroBased < 0 || zeroBased >= vertexCount)
    fail(at, "vertex index " + std::to_string(i) + " out of range (" + std::to_string(vertexCount) + " vertices so far)");
  return static_cast<int>(zeroBased);
}

}  // namespace

// Line by line: `v` appends a vertex, `f` a fan of triangles.
ObjMesh readObj(const std::string& path) try {
  config::LineReader in(path, "OBJ file", config::kObjLines);
  config::noteInputFile(path);
  ObjMesh mesh;
  std::string text;
  while (in.next(text)) {
    const LineContext at{path, static_cast<int>(in.lineNumber())};
    std::istringstream tokens(text.substr(0, text.find('#')));
    std::string keyword, token;
    if (!(tokens >> keyword)) continue;
    std::vector<std::string> args;
    while (tokens >> token) args.push_back(token);
    if (keyword == "v") {
      // x y z, then an optional w or r g b colour that terrain does not use.
      if (args.size() < 3) fail(at, "vertex needs x y z");
      // One at a time: the first bad coordinate is the one reported (argument order is unspecified).
      const double x = parseCoordinate(at, args[0]), y = parseCoordinate(at, args[1]), z = parseCoordinate(at, args[2]);
      mesh.vertices.emplace_back(x, y, z);
    } else if (keyword == "f") {
      if (args.size() < 3) fail(at, "face needs at least 3 vertices");
      const int n = static_cast<int>(mesh.vertices.size());
      const int first = parseCorner(at, args[0], n);
      int previous = parseCorner(at, args[1], n);
      for (std::size_t k = 2; k < args.size(); ++k) {
        const int next = parseCorner(at, args[k], n);
        mesh.triangles.push_back({first, previous, next});
        previous = next;
      }
      if (mesh.triangles.size() > config::kMaxObjTriangles)
        fail(at, "more than " + std::to_string(config::kMaxObjTriangles) + " triangles (the limit for an OBJ file)");
    }
  }
  if (mesh.triangles.empty()) throw TerrainFileError(path + ": OBJ file has no faces");
  return mesh;
} catch (const TerrainFileError&) {
  throw;
} catch (const std::runtime_error& e) {  // a limit of config::LineReader
  throw TerrainFileError(e.what());
}

}  // namespace bdfcar::terrain
