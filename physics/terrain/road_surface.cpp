// Heights of a generated road and its conversion to a mesh or a heightfield.
#include "terrain/road_surface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "terrain/terrain_mesh.h"
#include "portable_math.h"

namespace bdfcar::terrain {

namespace {

// Grids beyond this many points are refused: a typo in `cell` should fail
// with a message, not exhaust memory or take minutes. 5e6 points hold a road
// of 20 km x 60 m at 0.5 m cells; a 10-million-point mesh took 1 s to build
// under ASan (a fuzz_road timeout). 2e8 wave evaluations are about ten times
// the shipped rough.toml.
constexpr double kMaxGridPoints = 5.0e6;
constexpr double kMaxWaveEvaluations = 2.0e8;

// v in [lo, hi]; at an end, `side` says whether v is taken just above (+1) or below (-1) it.
bool within(double v, int side, double lo, double hi) {
  return (v > lo || (v == lo && side > 0)) && (v < hi || (v == hi && side < 0));
}

// Height added by one bump at (x, y).
double bumpHeight(const Bump& b, double x, double y, int sideX, int sideY) {
  if (!within(y, sideY, b.yMin, b.yMax)) return 0.0;
  if (b.profile == Bump::Profile::Step) return within(x, sideX, b.x, b.x + b.length) ? b.height : 0.0;
  if (x <= b.x || x >= b.x + b.length) return 0.0;
  return 0.5 * b.height * (1.0 - pm::cos(2.0 * std::numbers::pi * (x - b.x) / b.length));
}

bool verticalDrop(const Ramp& r) { return r.dropAngle >= std::numbers::pi / 2; }

// x where the rising face reaches the top, the top ends, and the falling face ends.
std::array<double, 3> rampBreaks(const Ramp& r) {
  const double topStart = r.x + r.height / pm::tan(r.angle);
  const double topEnd = topStart + r.topLength;
  return {topStart, topEnd, verticalDrop(r) ? topEnd : topEnd + r.height / pm::tan(r.dropAngle)};
}

// Height added by one ramp at (x, y): rise (x - x0) tan(angle), top, fall.
double rampHeight(const Ramp& r, double x, double y, int sideX, int sideY) {
  if (!within(y, sideY, r.yMin, r.yMax) || x <= r.x) return 0.0;
  const auto [topStart, topEnd, footEnd] = rampBreaks(r);
  if (x < topStart) return (x - r.x) * pm::tan(r.angle);
  if (x < topEnd || (x == topEnd && (sideX < 0 || !verticalDrop(r)))) return r.height;
  if (x < footEnd) return r.height - (x - topEnd) * pm::tan(r.dropAngle);
  return 0.0;
}

// Smooth 0 -> 1 taper over `fade` metres inside both ends of [xMin, xMax].
double taper(double xMin, double xMax, double fade, double x) {
  const double s = std::min(x - xMin, xMax - x) / fade;
  if (s <= 0.0) return 0.0;
  if (s >= 1.0) return 1.0;
  return s * s * (3.0 - 2.0 * s);
}

// Height added by one rough patch at (x, y).
double roughHeight(const RoughPatch& p, double x, double y) {
  const double fade = taper(p.xMin, p.xMax, p.fade, x);
  if (fade == 0.0) return 0.0;
  double h = 0.0;
  for (const RoughWave& w : p.waves) h += w.amplitude * pm::cos(w.kx * x + w.ky * y + w.phase);
  return fade * h;
}

// Height added by one corrugation at (x, y).
double corrugationHeight(const Corrugation& c, double x, double y, int sideY) {
  if (!within(y, sideY, c.yMin, c.yMax)) return 0.0;
  const double fade = taper(c.xMin, c.xMax, c.fade, x);
  if (fade == 0.0) return 0.0;
  return fade * 0.5 * c.height * (1.0 - pm::cos(2.0 * std::numbers::pi * (x - c.xMin) / c.wavelength));
}

// A grid line of the mesh; across a step line the height jumps.
struct GridLine {
  double at;
  bool step;
};

// A sample position along one axis and the side its height is taken from.
struct Sample {
  double at;
  int side;
};

// Refuse grids too large to hold or to compute (every rough wave is evaluated at every point).
void checkGridSize(const RoadSurface& road, double points, const char* what) {
  double waves = 0;
  for (const RoughPatch& p : road.rough) waves += static_cast<double>(p.waves.size());
  if (points > kMaxGridPoints || points * waves > kMaxWaveEvaluations)
    throw std::invalid_argument(std::string(what) + " would have " + std::to_string(static_cast<long long>(points)) +
                                " grid points (limit " + std::to_string(static_cast<long long>(kMaxGridPoints)) +
                                ", and " + std::to_string(static_cast<long long>(kMaxWaveEvaluations)) +
                                " times the rough waves): make `cell` larger or the surface smaller");
}

// Lines at most `cell` apart covering [from, to].
void addEvenLines(const RoadSurface& road, std::vector<GridLine>& lines, double from, double to, int minSegments = 1) {
  const double segments = std::max<double>(minSegments, std::ceil((to - from) / road.cell));
  checkGridSize(road, segments, "road mesh");  // too many lines is already too many points
  const int n = static_cast<int>(segments);
  for (int i = 0; i <= n; ++i) lines.push_back({from + (to - from) * i / n, false});
}

// Lateral edges of a feature (steps, when finite).
void addLateralEdges(std::vector<GridLine>& lines, double yMin, double yMax) {
  if (std::isfinite(yMin)) lines.push_back({yMin, true});
  if (std::isfinite(yMax)) lines.push_back({yMax, true});
}

// Sorted samples along an axis in [lo, hi]: every line once, a step line
// inside the range twice (the limit from below, then from above).
std::vector<Sample> samples(std::vector<GridLine> lines, double lo, double hi) {
  lines.push_back({lo, false});
  lines.push_back({hi, false});
  std::sort(lines.begin(), lines.end(), [](const GridLine& a, const GridLine& b) { return a.at < b.at; });
  std::vector<Sample> out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const double at = lines[i].at;
    if (at < lo || at > hi || (i > 0 && at == lines[i - 1].at)) continue;
    bool step = false;
    for (std::size_t j = i; j < lines.size() && lines[j].at == at; ++j) step = step || lines[j].step;
    if (step && at > lo && at < hi) {
      out.push_back({at, -1});
      out.push_back({at, +1});
    } else {
      out.push_back({at, at == hi ? -1 : +1});  // the surface's own edges look inward
    }
  }
  return out;
}

}  // namespace

// Sum of the heights of all features at (x, y) over the flat base z = 0.
double roadHeight(const RoadSurface& road, double x, double y, int sideX, int sideY) {
  double h = 0.0;
  for (const Bump& b : road.bumps) h += bumpHeight(b, x, y, sideX, sideY);
  for (const Ramp& r : road.ramps) h += rampHeight(r, x, y, sideX, sideY);
  for (const RoughPatch& p : road.rough) h += roughHeight(p, x, y);
  for (const Corrugation& c : road.corrugations) h += corrugationHeight(c, x, y, sideY);
  return h;
}

// Rectilinear grid through all feature edges, heights from roadHeight.
void buildRoadMesh(const RoadSurface& road, TerrainData& data) {
  std::vector<GridLine> xs, ys;
  for (const Bump& b : road.bumps) {
    if (b.profile == Bump::Profile::Step) {
      xs.push_back({b.x, true});
      xs.push_back({b.x + b.length, true});
    } else {
      addEvenLines(road, xs, b.x, b.x + b.length, 8);
    }
    addLateralEdges(ys, b.yMin, b.yMax);
  }
  for (const Ramp& r : road.ramps) {
    const auto [topStart, topEnd, footEnd] = rampBreaks(r);
    xs.insert(xs.end(), {{r.x, false}, {topStart, false}, {topEnd, verticalDrop(r)}, {footEnd, false}});
    addLateralEdges(ys, r.yMin, r.yMax);
  }
  for (const RoughPatch& p : road.rough) {
    if (p.xMax <= road.xMin || p.xMin >= road.xMax) continue;  // off the surface
    addEvenLines(road, xs, std::max(p.xMin, road.xMin), std::min(p.xMax, road.xMax));
    addEvenLines(road, ys, road.yMin, road.yMax);
  }
  for (const Corrugation& c : road.corrugations) {
    if (c.xMax <= road.xMin || c.xMin >= road.xMax) continue;
    // At least 8 lines a wavelength: the ridges keep their shape whatever `cell`.
    const double from = std::max(c.xMin, road.xMin), to = std::min(c.xMax, road.xMax);
    addEvenLines(road, xs, from, to, static_cast<int>(std::min(1e7, std::ceil(8.0 * (to - from) / c.wavelength))));
    addLateralEdges(ys, c.yMin, c.yMax);
  }
  const std::vector<Sample> sx = samples(xs, road.xMin, road.xMax), sy = samples(ys, road.yMin, road.yMax);
  checkGridSize(road, static_cast<double>(sx.size()) * static_cast<double>(sy.size()), "road mesh");

  data.kind = TerrainKind::Mesh;
  data.vertices.clear();
  data.vertices.reserve(sx.size() * sy.size());
  for (const Sample& y : sy)
    for (const Sample& x : sx) data.vertices.emplace_back(x.at, y.at, roadHeight(road, x.at, y.at, x.side, y.side));
  data.triangles = gridTriangles(static_cast<int>(sx.size()), static_cast<int>(sy.size()), data.vertices);
}

// Heights sampled every `cell` from (xMin, yMin); the far edges round up to whole cells.
void buildRoadHeightfield(const RoadSurface& road, TerrainData& data) {
  const double cols = std::ceil((road.xMax - road.xMin) / road.cell - 1e-9) + 1;
  const double rows = std::ceil((road.yMax - road.yMin) / road.cell - 1e-9) + 1;
  checkGridSize(road, cols * rows, "road heightfield");
  data.kind = TerrainKind::Heightfield;
  data.cols = static_cast<int>(cols);
  data.rows = static_cast<int>(rows);
  data.x0 = road.xMin;
  data.y0 = road.yMin;
  data.dx = data.dy = road.cell;
  data.heights.resize(static_cast<std::size_t>(data.rows) * data.cols);
  for (int row = 0; row < data.rows; ++row)
    for (int col = 0; col < data.cols; ++col)
      data.heights[static_cast<std::size_t>(row) * data.cols + col] =
          roadHeight(road, road.xMin + col * road.cell, road.yMin + row * road.cell);
}

}  // namespace bdfcar::terrain
