// The terrain loader: one TOML file in, checked TerrainData out.
#include "terrain/terrain_file.h"
#include "config/file_kind.h"

#include <filesystem>
#include <numbers>

#include "config/toml_reader.h"
#include "terrain/obj_file.h"
#include "terrain/road_file.h"
#include "terrain/track_file.h"

namespace bdfcar::terrain {

namespace {

using config::Dimension;
using config::Range;
using config::Table;

const Range kFriction{0.0, 2.0, true, false};
// Coordinates beyond 1000 km are typos, not terrain (the same bound as road_file.cpp).
const Range kCoordinate{-1e6, 1e6};
const Range kHeight{-1e4, 1e4};  // m, heightfield samples
const Range kDirection{-1e3, 1e3};

void readPlane(Table t, TerrainData& data) {
  t.rejectUnknownKeys({"point", "normal"});
  data.planePoint = t.has("point") ? t.vector3("point", Dimension::Length, kCoordinate) : Eigen::Vector3d::Zero().eval();
  const Eigen::Vector3d normal =
      t.has("normal") ? t.vector3("normal", Dimension::None, kDirection) : Eigen::Vector3d::UnitZ().eval();
  t.require(normal.norm() > 0.0, "normal", "a non-zero normal");
  data.planeNormal = normal.normalized();
}

// Triangles of the OBJ file named relative to the file naming it, moved by `offset`.
void readMesh(Table t, TerrainData& data) {
  t.rejectUnknownKeys({"obj", "offset"});
  if (t.string("obj").empty()) t.fail("expected a file name, got \"\"", "obj");
  const std::filesystem::path objPath = std::filesystem::path(t.folderOf("obj")) / t.string("obj");
  if (const auto why = config::notARegularFile(objPath)) t.fail("names OBJ file '" + objPath.string() + "', which " + *why, "obj");
  ObjMesh obj;
  try {
    obj = readObj(objPath.string());
  } catch (const TerrainFileError& e) {
    t.fail("names an unusable OBJ file: " + std::string(e.what()), "obj");
  }
  const Eigen::Vector3d offset = t.has("offset") ? t.vector3("offset", Dimension::Length, kCoordinate) : Eigen::Vector3d::Zero().eval();
  data.vertices = std::move(obj.vertices);
  for (Eigen::Vector3d& v : data.vertices) v += offset;
  data.triangles = std::move(obj.triangles);
}

// Rows of equal length, row r at y0 + r dy, column c at x0 + c dx.
void readHeightfield(Table t, TerrainData& data) {
  t.rejectUnknownKeys({"x0", "y0", "dx", "dy", "heights"});
  data.x0 = t.numberIn("x0", kCoordinate, 0.0);
  data.y0 = t.numberIn("y0", kCoordinate, 0.0);
  data.dx = t.numberIn("dx", {0.0, 1e3, true, false});
  data.dy = t.numberIn("dy", {0.0, 1e3, true, false});
  const std::vector<std::vector<double>> rows = t.grid("heights", 2, 2);
  data.heights.clear();
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (double h : rows[r]) {
      if (!kHeight.contains(h)) t.reject("heights", "rows of heights " + kHeight.text() + " m", static_cast<int>(r));
      data.heights.push_back(h);
    }
  data.rows = static_cast<int>(rows.size());
  data.cols = static_cast<int>(rows.front().size());
}

RoadMarkings readMarkings(Table t) {
  t.rejectUnknownKeys({"start_x", "end_x", "centre_y", "lanes", "lane_width"});
  RoadMarkings m;
  m.present = true;
  m.startX = t.numberIn("start_x", kCoordinate);
  m.endX = t.numberIn("end_x", kCoordinate);
  t.require(m.endX > m.startX, "end_x", "a number greater than start_x");
  m.centreY = t.numberIn("centre_y", kCoordinate, 0.0);
  m.lanes = static_cast<int>(t.integerIn("lanes", 1, 8, 2));
  m.laneWidth = t.numberIn("lane_width", {0.0, 10.0, true, false}, 3.5);
  return m;
}

// A rectangle of the ground plane with a friction of its own.
FrictionPatch readFrictionPatch(Table& t) {
  t.rejectUnknownKeys({"x_min", "x_max", "y_min", "y_max", "friction"});
  FrictionPatch f;
  f.xMin = t.numberIn("x_min", kCoordinate, -FrictionPatch::kInf);
  f.xMax = t.numberIn("x_max", kCoordinate, FrictionPatch::kInf);
  t.require(f.xMax > f.xMin, "x_max", "a number greater than x_min");
  f.yMin = t.numberIn("y_min", kCoordinate, -FrictionPatch::kInf);
  f.yMax = t.numberIn("y_max", kCoordinate, FrictionPatch::kInf);
  t.require(f.yMax > f.yMin, "y_max", "a number greater than y_min");
  f.friction = t.numberIn("friction", kFriction);
  return f;
}

// Tables each kind may have besides name, kind, friction, friction patches, markings and material.
std::vector<std::string_view> knownTopLevelKeys(const std::string& kind) {
  std::vector<std::string_view> keys = {"name", "kind", "friction", "friction_patches", "markings", "material"};
  if (kind == "road")
    keys.insert(keys.end(), {"build", "surface", "bumps", "ramps", "rough", "corrugations"});
  else if (kind == "ground")
    keys.insert(keys.end(), {"plane", "pieces"});
  else
    keys.push_back(kind);  // plane, mesh, heightfield, track: a table of that name
  return keys;
}

// What the surface is drawn as (`material`); a track is asphalt unless told, anything else grass.
Material readMaterial(Table& top, const std::string& kind) {
  const std::string m = top.choice("material", {"grass", "asphalt", "concrete", "gravel"},
                                   kind == "track" ? "asphalt" : "grass");
  return m == "asphalt" ? Material::Asphalt : m == "concrete" ? Material::Concrete
       : m == "gravel"  ? Material::Gravel  : Material::Grass;
}

TerrainData readTerrain(const std::string& tomlPath, bool asPiece);

// One [[pieces]] entry: a terrain file placed on the ground by `at` and `heading_deg`.
GroundPiece readPiece(Table& t) {
  t.rejectUnknownKeys({"name", "terrain", "at", "heading_deg"});
  GroundPiece p;
  const std::filesystem::path rel = t.string("terrain");
  const std::filesystem::path file = rel.is_absolute() ? rel : (std::filesystem::path(t.folderOf("terrain")) / rel).lexically_normal();
  if (const auto why = config::notARegularFile(file)) t.fail("names terrain file '" + file.string() + "', which " + *why, "terrain");
  p.terrain = readTerrain(file.string(), true);
  p.name = t.string("name", p.terrain.name);
  const std::vector<double> at = t.numbers("at", Dimension::Length, kCoordinate);
  t.require(at.size() == 2 || at.size() == 3, "at", "[x, y] or [x, y, z]");
  p.at = Eigen::Vector3d(at[0], at[1], at.size() == 3 ? at[2] : 0.0);
  p.heading = t.numberIn("heading_deg", {-360.0, 360.0}, 0.0) * std::numbers::pi / 180.0;
  return p;
}

// The surface of the declared kind into data.
void readSurface(Table& top, const std::string& kind, TerrainData& data) {
  if (kind == "plane") {
    data.kind = TerrainKind::Plane;
    if (top.has("plane")) readPlane(top.table("plane"), data);
  } else if (kind == "mesh") {
    data.kind = TerrainKind::Mesh;
    readMesh(top.table("mesh"), data);
  } else if (kind == "heightfield") {
    data.kind = TerrainKind::Heightfield;
    readHeightfield(top.table("heightfield"), data);
  } else if (kind == "track") {
    try {
      buildTrackMesh(readTrack(top.table("track"), data.material), data);
    } catch (const std::invalid_argument& e) {
      top.table("track").fail(e.what(), "segments");
    }
  } else if (kind == "ground") {
    data.kind = TerrainKind::Ground;
    if (top.has("plane")) readPlane(top.table("plane"), data);
    for (Table& t : top.tables("pieces")) data.pieces.push_back(readPiece(t));
    for (std::size_t i = 0; i < data.pieces.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (data.pieces[i].name == data.pieces[j].name)
          top.tables("pieces")[i].fail("is the name of an earlier piece too; give each piece its own `name`", "name");
  } else {
    const bool asMesh = top.choice("build", {"mesh", "heightfield"}, "mesh") == "mesh";
    const RoadSurface road = readRoadSurface(top);
    try {
      asMesh ? buildRoadMesh(road, data) : buildRoadHeightfield(road, data);
    } catch (const std::invalid_argument& e) {
      top.table("surface").fail(std::string("gives too large a grid: ") + e.what(), "cell");
    }
  }
}

// kind first (it decides which tables belong), then unknown keys, then values.
// A piece of a ground is bounded: not a plane, not a ground itself.
TerrainData readTerrain(const std::string& tomlPath, bool asPiece) {
  Table top = config::parseTomlFile(tomlPath);
  const std::string kind = asPiece ? top.choice("kind", {"mesh", "heightfield", "road", "track"})
                                   : top.choice("kind", {"plane", "mesh", "heightfield", "road", "track", "ground"});
  top.rejectUnknownKeys(knownTopLevelKeys(kind));
  TerrainData data;
  data.sourceFile = tomlPath;
  data.name = top.string("name", std::filesystem::path(tomlPath).stem().string());
  data.friction = top.numberIn("friction", kFriction);
  data.material = readMaterial(top, kind);
  for (Table& t : top.optionalTables("friction_patches")) data.frictionPatches.push_back(readFrictionPatch(t));
  if (top.has("markings")) data.road = readMarkings(top.table("markings"));
  readSurface(top, kind, data);
  return data;
}

}  // namespace

// The reader's ConfigError becomes the TerrainFileError callers catch, message unchanged.
TerrainData loadTerrain(const std::string& tomlPath) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(tomlPath, ec)) throw TerrainFileError(tomlPath + ": terrain file not found");
  TerrainData data;
  try {
    data = readTerrain(tomlPath, false);
  } catch (const config::ConfigError& e) {
    throw TerrainFileError(e.what());
  }
  try {
    checkTerrainData(data);
  } catch (const std::invalid_argument& e) {
    throw TerrainFileError(e.what());
  }
  return data;
}

}  // namespace bdfcar::terrain
