// Reading a generated road's parameters from TOML, with their accepted ranges.
#include "terrain/road_file.h"

#include <numbers>

namespace bdfcar::terrain {

namespace {

using config::Range;
using config::Table;

constexpr double kDegree = std::numbers::pi / 180.0;
// Coordinates beyond 1000 km are typos, not roads.
const Range kCoordinate{-1e6, 1e6};

// Optional lateral extent y_min < y_max of a feature (unbounded when absent).
void readLateralExtent(Table& t, double& yMin, double& yMax) {
  yMin = t.numberIn("y_min", kCoordinate, -kUnbounded);
  yMax = t.numberIn("y_max", kCoordinate, kUnbounded);
  t.require(yMax > yMin, "y_max", "a number greater than y_min");
}

void readSurfaceExtent(Table t, RoadSurface& road) {
  t.rejectUnknownKeys({"x_min", "x_max", "y_min", "y_max", "cell"});
  road.xMin = t.numberIn("x_min", kCoordinate);
  road.xMax = t.numberIn("x_max", kCoordinate);
  t.require(road.xMax > road.xMin, "x_max", "a number greater than x_min");
  road.yMin = t.numberIn("y_min", kCoordinate);
  road.yMax = t.numberIn("y_max", kCoordinate);
  t.require(road.yMax > road.yMin, "y_max", "a number greater than y_min");
  road.cell = t.numberIn("cell", {0.0, 10.0, true, false}, 0.25);
}

Bump readBump(Table& t) {
  t.rejectUnknownKeys({"profile", "x", "length", "height", "y_min", "y_max"});
  Bump b;
  b.profile = t.choice("profile", {"step", "cosine"}, "step") == "step" ? Bump::Profile::Step
                                                                                      : Bump::Profile::Cosine;
  b.x = t.numberIn("x", kCoordinate);
  b.length = t.numberIn("length", {0.0, 1e4, true, false});
  b.height = t.numberIn("height", {-1.0, 1.0});
  t.require(b.height != 0.0, "height", "a non-zero number");
  readLateralExtent(t, b.yMin, b.yMax);
  return b;
}

Ramp readRamp(Table& t) {
  t.rejectUnknownKeys({"x", "angle_deg", "height", "top_length", "drop_angle_deg", "y_min", "y_max"});
  Ramp r;
  r.x = t.numberIn("x", kCoordinate);
  r.angle = kDegree * t.numberIn("angle_deg", {0.0, 60.0, true, false});
  r.height = t.numberIn("height", {0.0, 5.0, true, false});
  r.topLength = t.numberIn("top_length", {0.0, 1e4}, 0.0);
  const double dropDegrees = t.numberIn("drop_angle_deg", {0.0, 90.0, true, false}, 90.0);
  // 90 degrees must mean exactly pi / 2 (a vertical lip), which 90 * (pi / 180) need not round to.
  r.dropAngle = dropDegrees == 90.0 ? std::numbers::pi / 2 : kDegree * dropDegrees;
  readLateralExtent(t, r.yMin, r.yMax);
  return r;
}

RoughPatch readRough(Table& t) {
  t.rejectUnknownKeys({"seed", "x_min", "x_max", "rms_height", "wavelength_min", "wavelength_max", "waves", "fade"});
  RoughPatch p;
  p.seed = static_cast<std::uint64_t>(t.integerIn("seed", 0, 1L << 62));
  p.xMin = t.numberIn("x_min", kCoordinate);
  p.xMax = t.numberIn("x_max", kCoordinate);
  t.require(p.xMax > p.xMin, "x_max", "a number greater than x_min");
  p.rmsHeight = t.numberIn("rms_height", {0.0, 0.5, true, false});
  p.wavelengthMin = t.numberIn("wavelength_min", {0.0, 1e3, true, false}, 0.5);
  p.wavelengthMax = t.numberIn("wavelength_max", {0.0, 1e3, true, false}, 20.0);
  t.require(p.wavelengthMax >= p.wavelengthMin, "wavelength_max", "a number >= wavelength_min");
  p.waveCount = static_cast<int>(t.integerIn("waves", 1, 4096, 64));
  p.fade = t.numberIn("fade", {0.0, 1e4, true, false}, 2.0);
  makeRoughWaves(p);
  return p;
}

Corrugation readCorrugation(Table& t) {
  t.rejectUnknownKeys({"x_min", "x_max", "wavelength", "height", "fade", "y_min", "y_max"});
  Corrugation c;
  c.xMin = t.numberIn("x_min", kCoordinate);
  c.xMax = t.numberIn("x_max", kCoordinate);
  t.require(c.xMax > c.xMin, "x_max", "a number greater than x_min");
  c.wavelength = t.numberIn("wavelength", {0.05, 100.0});
  c.height = t.numberIn("height", {0.0, 0.5, true, false});
  c.fade = t.numberIn("fade", {0.0, 1e4, true, false}, 2.0);
  readLateralExtent(t, c.yMin, c.yMax);
  return c;
}

}  // namespace

// The road's extent and features; the build choice stays with the caller.
RoadSurface readRoadSurface(Table& top) {
  RoadSurface road;
  readSurfaceExtent(top.table("surface"), road);
  for (Table& t : top.optionalTables("bumps")) road.bumps.push_back(readBump(t));
  for (Table& t : top.optionalTables("ramps")) road.ramps.push_back(readRamp(t));
  for (Table& t : top.optionalTables("rough")) road.rough.push_back(readRough(t));
  for (Table& t : top.optionalTables("corrugations")) road.corrugations.push_back(readCorrugation(t));
  return road;
}

}  // namespace bdfcar::terrain
