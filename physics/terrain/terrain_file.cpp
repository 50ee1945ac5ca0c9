// The terrain loader: one TOML file in, checked TerrainData out.
#include "terrain/terrain_file.h"

#include <filesystem>

#include "terrain/obj_file.h"
#include "terrain/road_file.h"
#include "terrain/toml_fields.h"

namespace bdfcar::terrain {

namespace {

using toml_fields::Range;
using toml_fields::Table;

const Range kFriction{0.0, 2.0, true, false};

void readPlane(const Table& t, TerrainData& data) {
  toml_fields::rejectUnknownKeys(t, {"point", "normal"});
  data.planePoint = toml_fields::vector3(t, "point", Eigen::Vector3d::Zero());
  const Eigen::Vector3d normal = toml_fields::vector3(t, "normal", Eigen::Vector3d::UnitZ());
  toml_fields::require(normal.norm() > 0.0, t, "normal", "must not be zero");
  data.planeNormal = normal.normalized();
}

// Triangles of the OBJ file named relative to the .toml, moved by `offset`.
void readMesh(const Table& t, const std::string& tomlPath, TerrainData& data) {
  toml_fields::rejectUnknownKeys(t, {"obj", "offset"});
  const std::filesystem::path objPath = std::filesystem::path(tomlPath).parent_path() / toml_fields::text(t, "obj");
  std::error_code ec;
  toml_fields::require(std::filesystem::is_regular_file(objPath, ec), t, "obj",
                       "names OBJ file '" + objPath.string() + "', which does not exist");
  ObjMesh obj;
  try {
    obj = readObj(objPath.string());
  } catch (const TerrainFileError& e) {
    toml_fields::require(false, t, "obj", "names an unusable OBJ file: " + std::string(e.what()));
  }
  const Eigen::Vector3d offset = toml_fields::vector3(t, "offset", Eigen::Vector3d::Zero());
  data.vertices = std::move(obj.vertices);
  for (Eigen::Vector3d& v : data.vertices) v += offset;
  data.triangles = std::move(obj.triangles);
}

// Rows of equal length, row r at y0 + r dy, column c at x0 + c dx.
void readHeightfield(const Table& t, TerrainData& data) {
  toml_fields::rejectUnknownKeys(t, {"x0", "y0", "dx", "dy", "heights"});
  data.x0 = toml_fields::number(t, "x0", {}, 0.0);
  data.y0 = toml_fields::number(t, "y0", {}, 0.0);
  data.dx = toml_fields::number(t, "dx", {0.0, 1e3, true, false});
  data.dy = toml_fields::number(t, "dy", {0.0, 1e3, true, false});
  toml_fields::require(toml_fields::has(t, "heights"), t, "heights", "is missing (an array of rows of heights)");
  const toml_fields::Value& heights = t.value.as_table().at("heights");
  const std::string name = toml_fields::keyName(t, "heights");
  if (!heights.is_array() || heights.as_array().size() < 2)
    toml_fields::fail(heights, name + " must be an array of at least 2 rows");
  data.heights.clear();
  data.cols = 0;
  for (const toml_fields::Value& row : heights.as_array()) {
    if (!row.is_array() || row.as_array().size() < 2)
      toml_fields::fail(row, name + ": each row must be an array of at least 2 numbers");
    if (data.cols == 0) data.cols = static_cast<int>(row.as_array().size());
    if (static_cast<int>(row.as_array().size()) != data.cols)
      toml_fields::fail(row, name + ": every row must have " + std::to_string(data.cols) + " heights like the first, got " +
                                 std::to_string(row.as_array().size()));
    for (const toml_fields::Value& h : row.as_array()) data.heights.push_back(toml_fields::asNumber(h, name + " element"));
  }
  data.rows = static_cast<int>(heights.as_array().size());
}

RoadMarkings readMarkings(const Table& t) {
  toml_fields::rejectUnknownKeys(t, {"start_x", "end_x", "centre_y", "lanes", "lane_width"});
  RoadMarkings m;
  m.present = true;
  m.startX = toml_fields::number(t, "start_x", {});
  m.endX = toml_fields::number(t, "end_x", {});
  toml_fields::require(m.endX > m.startX, t, "end_x", "must be greater than start_x");
  m.centreY = toml_fields::number(t, "centre_y", {}, 0.0);
  m.lanes = static_cast<int>(toml_fields::integer(t, "lanes", 1, 8, 2));
  m.laneWidth = toml_fields::number(t, "lane_width", {0.0, 10.0, true, false}, 3.5);
  return m;
}

// Tables each kind may have besides name, kind, friction and markings.
std::vector<std::string_view> knownTopLevelKeys(const std::string& kind) {
  std::vector<std::string_view> keys = {"name", "kind", "friction", "markings"};
  if (kind == "road")
    keys.insert(keys.end(), {"build", "surface", "bumps", "ramps", "rough"});
  else
    keys.push_back(kind == "plane" ? "plane" : kind == "mesh" ? "mesh" : "heightfield");
  return keys;
}

// The surface of the declared kind into data.
void readSurface(const Table& top, const std::string& kind, const std::string& tomlPath, TerrainData& data) {
  if (kind == "plane") {
    data.kind = TerrainKind::Plane;
    if (toml_fields::has(top, "plane")) readPlane(toml_fields::subtable(top, "plane"), data);
  } else if (kind == "mesh") {
    data.kind = TerrainKind::Mesh;
    readMesh(toml_fields::subtable(top, "mesh"), tomlPath, data);
  } else if (kind == "heightfield") {
    data.kind = TerrainKind::Heightfield;
    readHeightfield(toml_fields::subtable(top, "heightfield"), data);
  } else {
    const bool asMesh = toml_fields::choice(top, "build", {"mesh", "heightfield"}, "mesh") == "mesh";
    const RoadSurface road = readRoadSurface(top);
    try {
      asMesh ? buildRoadMesh(road, data) : buildRoadHeightfield(road, data);
    } catch (const std::invalid_argument& e) {
      toml_fields::require(false, toml_fields::subtable(top, "surface"), "cell", std::string("gives too large a grid: ") + e.what());
    }
  }
}

}  // namespace

// kind first (it decides which tables belong), then unknown keys, then values.
TerrainData loadTerrain(const std::string& tomlPath) {
  const toml_fields::Value root = toml_fields::parseFile(tomlPath);
  const Table top{root, ""};
  const std::string kind = toml_fields::choice(top, "kind", {"plane", "mesh", "heightfield", "road"});
  toml_fields::rejectUnknownKeys(top, knownTopLevelKeys(kind));
  TerrainData data;
  data.sourceFile = tomlPath;
  data.name = toml_fields::text(top, "name", std::filesystem::path(tomlPath).stem().string());
  data.friction = toml_fields::number(top, "friction", kFriction);
  if (toml_fields::has(top, "markings")) data.road = readMarkings(toml_fields::subtable(top, "markings"));
  readSurface(top, kind, tomlPath, data);
  try {
    checkTerrainData(data);
  } catch (const std::invalid_argument& e) {
    throw TerrainFileError(e.what());
  }
  return data;
}

}  // namespace bdfcar::terrain
