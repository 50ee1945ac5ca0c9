#include <osg/Geode>
#include <osg/LOD>
#include <osg/PolygonOffset>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "render/nodes.h"
#include "render/osg_convert.h"
#include "render/terrain_lod.h"
#include "render/textures.h"

namespace bdfcar::render {
namespace {

constexpr double kPlaneStep = 2.0;     // m between cross-sections along x on a plane
constexpr double kLineWidth = 0.15, kDash = 3.0, kGap = 6.0;  // m

// Cross-sections along x close enough to follow the surface: its grid
// spacing (a heightfield's; a mesh's triangles' shortest edges, their median:
// a generated road's strips are narrow along x and long across), 2 m on a plane.
double drapeStep(const terrain::TerrainData& data) {
  using terrain::TerrainKind;
  if (data.kind == TerrainKind::Heightfield) return std::clamp(std::min(data.dx, data.dy), 0.02, kPlaneStep);
  if (data.kind != TerrainKind::Mesh || data.triangles.empty()) return kPlaneStep;
  std::vector<double> edges;
  const std::size_t every = std::max<std::size_t>(1, data.triangles.size() / 4096);
  for (std::size_t k = 0; k < data.triangles.size(); k += every) {
    const auto& t = data.triangles[k];
    double shortest = std::numeric_limits<double>::infinity();
    for (int e = 0; e < 3; ++e)
      shortest = std::min(shortest, (data.vertices[t[(e + 1) % 3]] - data.vertices[t[e]]).head<2>().norm());
    edges.push_back(shortest);
  }
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  return std::clamp(edges[edges.size() / 2], 0.02, kPlaneStep);
}

// Cross-sections of the strip y in [y0, y1] from x0 to x1: the surface is
// sampled every `step` m along both edges, and a cross-section kept only
// where the edges, drawn straight from the last one kept, would stray more
// than `tolerance` from a sample, and at least every `longest` m (on a
// plane: one quad every 2 m near; on the rough road: closer where it is
// rougher).
constexpr double kDrapeTolerance = 0.004;  // m, well under the paint's 2 cm lift
std::vector<double> drapeSections(const SurfaceSampler& ground, double step, double x0, double x1, double y0, double y1,
                                  double tolerance, double longest) {
  const int n = std::max(1, static_cast<int>(std::ceil((x1 - x0) / step)));
  std::vector<double> x(n + 1), z0(n + 1), z1(n + 1);
  for (int i = 0; i <= n; ++i) {
    x[i] = x0 + (x1 - x0) * i / n;
    z0[i] = ground.heightOr(x[i], y0, 0.0);
    z1[i] = ground.heightOr(x[i], y1, 0.0);
  }
  std::vector<double> kept{x[0]};
  int from = 0;
  auto straight = [&](int a, int b) {  // do both edges stay within tolerance of their chords from a to b?
    for (int i = a + 1; i < b; ++i) {
      const double w = (x[i] - x[a]) / (x[b] - x[a]);
      if (std::abs(z0[a] + w * (z0[b] - z0[a]) - z0[i]) > tolerance ||
          std::abs(z1[a] + w * (z1[b] - z1[a]) - z1[i]) > tolerance)
        return false;
    }
    return true;
  };
  const int samples = std::max(1, static_cast<int>(longest / step));  // at most `longest` between sections
  for (int i = 1; i <= n; ++i) {
    if (i - from < samples && i < n && straight(from, i + 1)) continue;
    kept.push_back(x[i]);
    from = i;
  }
  return kept;
}

// How closely paint follows the surface, finest first: a level drawn with
// tolerance t is lifted by t more (its chords may dip t below the surface)
// and so strays up to 2 t from the finest; it is drawn from where 2 t is under
// a pixel. Far from the camera the rough road's lines need a few sections
// where near they need hundreds.
struct DrapeLevel {
  double tolerance, longest;  // m
};
constexpr std::array<DrapeLevel, 3> kDrapeLevels{{{kDrapeTolerance, kPlaneStep}, {0.02, 4 * kPlaneStep},
                                                  {0.08, 16 * kPlaneStep}}};

// Textured strip y in [y0, y1] from x0 to x1, lifted `lift` m above the
// terrain, its cross-sections following the surface (drapeSections) as
// closely as `level` asks.
void addStrip(TriangleBuilder& tb, const SurfaceSampler& ground, double step, double x0, double x1, double y0,
              double y1, double lift, const osg::Vec4& colour, float texRepeat, const DrapeLevel& level = kDrapeLevels[0]) {
  const std::vector<double> xs = drapeSections(ground, step, x0, x1, y0, y1, level.tolerance, level.longest);
  auto at = [&](double x, double y) {
    return osg::Vec3(float(x), float(y), float(ground.heightOr(x, y, 0.0) + lift));
  };
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double xa = xs[i], xb = xs[i + 1];
    const osg::Vec3 q[4] = {at(xa, y0), at(xb, y0), at(xb, y1), at(xa, y1)};
    osg::Vec3 normal = (q[1] - q[0]) ^ (q[3] - q[0]);
    normal.normalize();
    for (int t : {0, 1, 2, 0, 2, 3})
      tb.vertex(q[t], normal, colour, osg::Vec2(q[t].x() / texRepeat, q[t].y() / texRepeat));
  }
}

// Geode of one strip builder, pulled towards the eye by `offsetUnits` to win against the layer beneath,
// drawn in render bin `bin` (top layers first: see nodes.h).
osg::ref_ptr<osg::Geode> layer(TriangleBuilder& tb, float offsetUnits, int bin) {
  osg::ref_ptr<osg::Geode> g = new osg::Geode;
  g->addDrawable(tb.build());
  g->getOrCreateStateSet()->setAttributeAndModes(new osg::PolygonOffset(-1.0f, offsetUnits), osg::StateAttribute::ON);
  g->getOrCreateStateSet()->setRenderBinDetails(bin, "RenderBin");
  return g;
}

}  // namespace

// White paint (solid edge lines, dashed lines between lanes) draped on the
// surface; on a plane (a ground's plane) an asphalt ribbon under it. On relief the surface's own
// triangles are the asphalt (terrain::triangulate colours them), so the
// road shows its relief and no ribbon cuts through it.
osg::ref_ptr<osg::Node> makeRoadNode(const terrain::TerrainData& data, const SurfaceSampler& ground) {
  osg::ref_ptr<osg::Group> group = new osg::Group;
  const terrain::RoadMarkings& road = data.road;
  if (!road.present || road.endX <= road.startX || road.lanes < 1) return group;
  const double half = 0.5 * road.lanes * road.laneWidth;
  const double step = drapeStep(data);

  if (data.kind == terrain::TerrainKind::Plane || data.kind == terrain::TerrainKind::Ground) {
    TriangleBuilder asphalt;
    asphalt.enableTexcoords();
    const double edge = road.asphaltHalfWidth();
    addStrip(asphalt, ground, step, road.startX, road.endX, road.centreY - edge, road.centreY + edge, 0.01,
             rgba(1, 1, 1), 4.0f);
    osg::ref_ptr<osg::Geode> asphaltNode = layer(asphalt, -2.0f, kBinAsphalt);
    asphaltNode->getOrCreateStateSet()->setTextureAttributeAndModes(0, asphaltTexture().get(), osg::StateAttribute::ON);
    group->addChild(asphaltNode);
  }

  // Paint in pieces of kPaintTile m along the road, so that culling skips
  // what is out of view, each piece draped as closely as its distance asks
  // (kDrapeLevels).
  constexpr double kPaintTile = 50.0, kPaintLift = 0.02;
  const osg::Vec4 white = rgba(0.93, 0.93, 0.9);
  auto paintPiece = [&](int tile, const DrapeLevel& level, TriangleBuilder& tb) {
    const double tileStart = tile * kPaintTile, tileEnd = tileStart + kPaintTile, lift = kPaintLift + (level.tolerance - kDrapeTolerance);
    for (double side : {-1.0, 1.0}) {
      const double y = road.centreY + side * (half - 0.5 * kLineWidth);
      const double x0 = std::max(road.startX, tileStart), x1 = std::min(road.endX, tileEnd);
      if (x1 > x0) addStrip(tb, ground, step, x0, x1, y - 0.5 * kLineWidth, y + 0.5 * kLineWidth, lift, white, 1.0f, level);
    }
    for (int lane = 1; lane < road.lanes; ++lane) {
      const double y = road.centreY - half + lane * road.laneWidth;
      for (double x = road.startX; x < road.endX; x += kDash + kGap)
        if (std::floor(x / kPaintTile) == tile)
          addStrip(tb, ground, step, x, std::min(x + kDash, road.endX), y - 0.5 * kLineWidth, y + 0.5 * kLineWidth,
                   lift, white, 1.0f, level);
    }
  };
  osg::ref_ptr<osg::StateSet> paintState = new osg::StateSet;
  paintState->setAttributeAndModes(new osg::PolygonOffset(-1.0f, -4.0f), osg::StateAttribute::ON);
  paintState->setRenderBinDetails(kBinRoadPaint, "RenderBin");
  const int first = static_cast<int>(std::floor(road.startX / kPaintTile)),
            last = static_cast<int>(std::floor(std::nextafter(road.endX, road.startX) / kPaintTile));
  for (int tile = first; tile <= last; ++tile) {
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    float from = 0.0f;
    for (std::size_t k = 0; k < kDrapeLevels.size(); ++k) {
      TriangleBuilder tb;
      paintPiece(tile, kDrapeLevels[k], tb);
      if (tb.v->empty()) break;
      osg::ref_ptr<osg::Geode> geode = new osg::Geode;
      geode->addDrawable(tb.build());
      geode->setStateSet(paintState.get());
      const float radius = geode->getBound().radius();
      const float to = k + 1 < kDrapeLevels.size()
                           ? radius + underAPixelFrom(float(2 * kDrapeLevels[k + 1].tolerance))
                           : std::numeric_limits<float>::max();
      if (to > from) lod->addChild(geode, from, to);
      from = std::max(from, to);
    }
    if (lod->getNumChildren() > 0) group->addChild(lod);
  }
  return group;
}

}  // namespace bdfcar::render
