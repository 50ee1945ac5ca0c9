// Reading a generated road's parameters from TOML, with their accepted ranges.
#include "terrain/road_file.h"

#include <numbers>

namespace bdfcar::terrain {

namespace {

using toml_fields::Range;
using toml_fields::Table;

constexpr double kDegree = std::numbers::pi / 180.0;
// Coordinates beyond 1000 km are typos, not roads.
const Range kCoordinate{-1e6, 1e6};

// Optional lateral extent y_min < y_max of a feature (unbounded when absent).
void readLateralExtent(const Table& t, double& yMin, double& yMax) {
  yMin = toml_fields::number(t, "y_min", kCoordinate, -kUnbounded);
  yMax = toml_fields::number(t, "y_max", kCoordinate, kUnbounded);
  toml_fields::require(yMax > yMin, t, "y_max", "must be greater than y_min");
}

void readSurfaceExtent(const Table& t, RoadSurface& road) {
  toml_fields::rejectUnknownKeys(t, {"x_min", "x_max", "y_min", "y_max", "cell"});
  road.xMin = toml_fields::number(t, "x_min", kCoordinate);
  road.xMax = toml_fields::number(t, "x_max", kCoordinate);
  toml_fields::require(road.xMax > road.xMin, t, "x_max", "must be greater than x_min");
  road.yMin = toml_fields::number(t, "y_min", kCoordinate);
  road.yMax = toml_fields::number(t, "y_max", kCoordinate);
  toml_fields::require(road.yMax > road.yMin, t, "y_max", "must be greater than y_min");
  road.cell = toml_fields::number(t, "cell", {0.0, 10.0, true, false}, 0.25);
}

Bump readBump(const Table& t) {
  toml_fields::rejectUnknownKeys(t, {"profile", "x", "length", "height", "y_min", "y_max"});
  Bump b;
  b.profile = toml_fields::choice(t, "profile", {"step", "cosine"}, "step") == "step" ? Bump::Profile::Step
                                                                                      : Bump::Profile::Cosine;
  b.x = toml_fields::number(t, "x", kCoordinate);
  b.length = toml_fields::number(t, "length", {0.0, 1e4, true, false});
  b.height = toml_fields::number(t, "height", {-1.0, 1.0});
  toml_fields::require(b.height != 0.0, t, "height", "must not be zero");
  readLateralExtent(t, b.yMin, b.yMax);
  return b;
}

Ramp readRamp(const Table& t) {
  toml_fields::rejectUnknownKeys(t, {"x", "angle_deg", "height", "top_length", "drop_angle_deg", "y_min", "y_max"});
  Ramp r;
  r.x = toml_fields::number(t, "x", kCoordinate);
  r.angle = kDegree * toml_fields::number(t, "angle_deg", {0.0, 60.0, true, false});
  r.height = toml_fields::number(t, "height", {0.0, 5.0, true, false});
  r.topLength = toml_fields::number(t, "top_length", {0.0, 1e4}, 0.0);
  const double dropDegrees = toml_fields::number(t, "drop_angle_deg", {0.0, 90.0, true, false}, 90.0);
  // 90 degrees must mean exactly pi / 2 (a vertical lip), which 90 * (pi / 180) need not round to.
  r.dropAngle = dropDegrees == 90.0 ? std::numbers::pi / 2 : kDegree * dropDegrees;
  readLateralExtent(t, r.yMin, r.yMax);
  return r;
}

RoughPatch readRough(const Table& t) {
  toml_fields::rejectUnknownKeys(
      t, {"seed", "x_min", "x_max", "rms_height", "wavelength_min", "wavelength_max", "waves", "fade"});
  RoughPatch p;
  p.seed = static_cast<std::uint64_t>(toml_fields::integer(t, "seed", 0, 1LL << 62));
  p.xMin = toml_fields::number(t, "x_min", kCoordinate);
  p.xMax = toml_fields::number(t, "x_max", kCoordinate);
  toml_fields::require(p.xMax > p.xMin, t, "x_max", "must be greater than x_min");
  p.rmsHeight = toml_fields::number(t, "rms_height", {0.0, 0.5, true, false});
  p.wavelengthMin = toml_fields::number(t, "wavelength_min", {0.0, 1e3, true, false}, 0.5);
  p.wavelengthMax = toml_fields::number(t, "wavelength_max", {0.0, 1e3, true, false}, 20.0);
  toml_fields::require(p.wavelengthMax >= p.wavelengthMin, t, "wavelength_max", "must be >= wavelength_min");
  p.waveCount = static_cast<int>(toml_fields::integer(t, "waves", 1, 4096, 64));
  p.fade = toml_fields::number(t, "fade", {0.0, 1e4, true, false}, 2.0);
  makeRoughWaves(p);
  return p;
}

}  // namespace

// The road's extent and features; the build choice stays with the caller.
RoadSurface readRoadSurface(const Table& top) {
  RoadSurface road;
  readSurfaceExtent(toml_fields::subtable(top, "surface"), road);
  for (const Table& t : toml_fields::tableArray(top, "bumps")) road.bumps.push_back(readBump(t));
  for (const Table& t : toml_fields::tableArray(top, "ramps")) road.ramps.push_back(readRamp(t));
  for (const Table& t : toml_fields::tableArray(top, "rough")) road.rough.push_back(readRough(t));
  return road;
}

}  // namespace bdfcar::terrain
