// The track generator: centre line, then a grid of cross-sections along it.
#include "terrain/track.h"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>
#include "portable_math.h"

namespace bdfcar::terrain {

namespace {

constexpr double kCurbRise = 0.15;         // m across which a curb's faces rise to its top
constexpr double kCurbTaper = 2.0;         // m along which a curb rises from nothing at each end of its arc
constexpr double kCurbStripe = 1.0;        // m, length of one red or white stripe
constexpr double kStraightChord = 50.0;    // m, longest chord along a straight

Eigen::Vector2d leftOf(double heading) { return {-pm::sin(heading), pm::cos(heading)}; }

double wrapAngle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a == -std::numbers::pi ? std::numbers::pi : a;
}

bool curbedSide(const TrackSegment& seg, int side) {
  if (seg.radius <= 0 || seg.curbs == TrackSegment::Curbs::None) return false;
  const int inside = seg.angle > 0 ? +1 : -1;
  switch (seg.curbs) {
    case TrackSegment::Curbs::Inside: return side == inside;
    case TrackSegment::Curbs::Outside: return side == -inside;
    case TrackSegment::Curbs::Both: return true;
    case TrackSegment::Curbs::None: break;
  }
  return false;
}

// A grid of vertices, one row per centre-line point and one column per lateral offset.
struct Grid {
  int columns = 0, first = 0;  // offset of its first vertex in the mesh
  int at(int point, int column) const { return first + point * columns + column; }
};

// Quads between consecutive rows as two counter-clockwise triangles (forward, then left).
void addQuad(TerrainData& data, const Grid& g, int row0, int row1, int col, Material m) {
  const int a = g.at(row0, col), b = g.at(row1, col), c = g.at(row1, col + 1), d = g.at(row0, col + 1);
  data.triangles.push_back({a, b, c});
  data.triangles.push_back({a, c, d});
  data.triangleMaterials.insert(data.triangleMaterials.end(), 2, m);
}

}  // namespace

std::vector<CentreLinePoint> sampleCentreLine(const Track& track) {
  std::vector<CentreLinePoint> out{CentreLinePoint{}};
  for (int k = 0; k < static_cast<int>(track.segments.size()); ++k) {
    const TrackSegment& seg = track.segments[k];
    const CentreLinePoint start = out.back();
    const bool curbs = seg.curbs != TrackSegment::Curbs::None;
    const double chord = seg.radius > 0 ? (curbs ? std::min(track.cell, kCurbStripe) : track.cell) : kStraightChord;
    const int n = std::max(1, static_cast<int>(std::ceil(seg.arcLength() / chord - 1e-9)));
    const double sign = seg.angle >= 0 ? 1.0 : -1.0;
    const Eigen::Vector2d centre = start.p + sign * seg.radius * leftOf(start.heading);
    for (int i = 1; i <= n; ++i) {
      const double f = static_cast<double>(i) / n;
      CentreLinePoint q;
      q.segment = k;
      q.s = start.s + f * seg.arcLength();
      if (seg.radius > 0) {
        q.heading = start.heading + f * seg.angle;
        q.p = centre - sign * seg.radius * leftOf(q.heading);
      } else {
        q.heading = start.heading;
        q.p = start.p + f * seg.length * Eigen::Vector2d(pm::cos(start.heading), pm::sin(start.heading));
      }
      out.push_back(q);
    }
  }
  return out;
}

void closureError(const Track& track, double& gap, double& angle) {
  const std::vector<CentreLinePoint> line = sampleCentreLine(track);
  gap = (line.back().p - line.front().p).norm();
  angle = wrapAngle(line.back().heading - line.front().heading);
}

void buildTrackMesh(const Track& track, TerrainData& data) {
  if (track.segments.empty()) throw std::invalid_argument("a track needs at least one segment");
  const std::vector<CentreLinePoint> line = sampleCentreLine(track);
  const int n = static_cast<int>(line.size());
  double gap = 0, angle = 0;
  closureError(track, gap, angle);
  if (track.closed && (gap > kClosureGap || std::abs(angle) > kClosureAngle))
    throw std::invalid_argument("the circuit does not close: its centre line ends " + std::to_string(gap) +
                                " m from its start, heading " + std::to_string(angle * 180 / std::numbers::pi) +
                                " deg off");
  // A circuit's last row is its first: the small closure error spreads over the last chord.
  auto row = [&](int i) { return track.closed && i == n - 1 ? 0 : i; };
  const double half = 0.5 * track.width, lw = std::min(track.lineWidth, 0.25 * track.width);

  data.kind = TerrainKind::Mesh;
  data.vertices.clear();
  data.triangles.clear();
  data.triangleMaterials.clear();
  data.material = track.surface;

  // The ribbon: paint | surface | paint across, z = 0.
  std::vector<double> across = lw > 0 ? std::vector<double>{-half, -half + lw, half - lw, half}
                                      : std::vector<double>{-half, half};
  const Grid ribbon{static_cast<int>(across.size()), 0};
  for (const CentreLinePoint& q : line)
    for (double l : across) {
      const Eigen::Vector2d p = q.p + l * leftOf(q.heading);
      data.vertices.emplace_back(p.x(), p.y(), 0.0);
    }
  for (int i = 1; i < n; ++i)
    for (int c = 0; c + 1 < ribbon.columns; ++c) {
      const bool paint = lw > 0 && c != 1;
      addQuad(data, ribbon, row(i - 1), row(i), c, paint ? Material::Paint : track.surface);
    }

  // Curbs: beyond each edge of a curbed arc, a flat-topped strip that rises
  // from nothing over kCurbTaper at both ends of the arc; red and white stripes.
  const double cw = track.curbWidth, rise = std::min(kCurbRise, 0.25 * cw);
  for (int side : {+1, -1}) {
    if (std::none_of(track.segments.begin(), track.segments.end(),
                     [side](const TrackSegment& seg) { return curbedSide(seg, side); }))
      continue;
    // Columns ordered by increasing lateral offset, so quads wind counter-clockwise.
    const std::vector<double> out = side > 0 ? std::vector<double>{0, rise, cw - rise, cw}
                                             : std::vector<double>{cw, cw - rise, rise, 0};
    const Grid curb{4, static_cast<int>(data.vertices.size())};
    for (int i = 0; i < n; ++i) {
      // Height at this row: the arc the row belongs to, or the one starting at it.
      double height = 0;
      for (int k : {line[i].segment, i + 1 < n ? line[i + 1].segment : -1}) {
        if (k < 0 || !curbedSide(track.segments[k], side)) continue;
        const TrackSegment& seg = track.segments[k];
        double s0 = 0;
        for (int j = 0; j < k; ++j) s0 += track.segments[j].arcLength();
        const double taper = std::min(kCurbTaper, 0.25 * seg.arcLength());
        const double d = std::min(line[i].s - s0, s0 + seg.arcLength() - line[i].s);
        height = std::max(height, track.curbHeight * std::clamp(d / taper, 0.0, 1.0));
      }
      for (int c = 0; c < 4; ++c) {
        const bool top = c == 1 || c == 2;
        const Eigen::Vector2d p = line[i].p + side * (half + out[c]) * leftOf(line[i].heading);
        data.vertices.emplace_back(p.x(), p.y(), top ? height : 0.0);
      }
    }
    for (int i = 1; i < n; ++i) {
      if (!curbedSide(track.segments[line[i].segment], side)) continue;
      const Material stripe = (i % 2) ? Material::CurbRed : Material::CurbWhite;
      for (int c = 0; c < 3; ++c) addQuad(data, curb, i - 1, i, c, stripe);
    }
  }

  data.centreLine.clear();
  for (int i = 0; i < (track.closed ? n - 1 : n); ++i) data.centreLine.push_back(line[i].p);
  data.centreLineClosed = track.closed;
  data.centreLineWidth = track.width;
}

}  // namespace bdfcar::terrain
