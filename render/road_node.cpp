#include <osg/Geode>
#include <osg/PolygonOffset>

#include <algorithm>
#include <cmath>

#include "render/nodes.h"
#include "render/osg_convert.h"
#include "render/textures.h"

namespace bdfcar::render {
namespace {

constexpr double kStep = 2.0;          // m between road cross-sections along x
constexpr double kShoulder = 0.6;      // m of asphalt beyond each edge line
constexpr double kLineWidth = 0.15, kDash = 3.0, kGap = 6.0;  // m

// Textured strip y in [y0, y1] from x0 to x1, lifted `lift` m above the terrain.
void addStrip(TriangleBuilder& tb, const SurfaceSampler& ground, double x0, double x1, double y0, double y1,
              double lift, const osg::Vec4& colour, float texRepeat) {
  const int n = std::max(1, static_cast<int>(std::ceil((x1 - x0) / kStep)));
  auto at = [&](double x, double y) {
    return osg::Vec3(float(x), float(y), float(ground.heightOr(x, y, 0.0) + lift));
  };
  for (int i = 0; i < n; ++i) {
    const double xa = x0 + (x1 - x0) * i / n, xb = x0 + (x1 - x0) * (i + 1) / n;
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

// Asphalt ribbon plus white paint: solid edge lines, dashed lines between lanes.
osg::ref_ptr<osg::Node> makeRoadNode(const terrain::RoadMarkings& road, const SurfaceSampler& ground) {
  osg::ref_ptr<osg::Group> group = new osg::Group;
  if (!road.present || road.endX <= road.startX || road.lanes < 1) return group;
  const double half = 0.5 * road.lanes * road.laneWidth;

  TriangleBuilder asphalt;
  asphalt.enableTexcoords();
  addStrip(asphalt, ground, road.startX, road.endX, road.centreY - half - kShoulder, road.centreY + half + kShoulder,
           0.01, rgba(1, 1, 1), 4.0f);
  osg::ref_ptr<osg::Geode> asphaltNode = layer(asphalt, -2.0f, kBinAsphalt);
  asphaltNode->getOrCreateStateSet()->setTextureAttributeAndModes(0, asphaltTexture().get(), osg::StateAttribute::ON);
  group->addChild(asphaltNode);

  TriangleBuilder paint;
  const osg::Vec4 white = rgba(0.93, 0.93, 0.9);
  for (double side : {-1.0, 1.0}) {
    const double y = road.centreY + side * (half - 0.5 * kLineWidth);
    addStrip(paint, ground, road.startX, road.endX, y - 0.5 * kLineWidth, y + 0.5 * kLineWidth, 0.02, white, 1.0f);
  }
  for (int lane = 1; lane < road.lanes; ++lane) {
    const double y = road.centreY - half + lane * road.laneWidth;
    for (double x = road.startX; x < road.endX; x += kDash + kGap)
      addStrip(paint, ground, x, std::min(x + kDash, road.endX), y - 0.5 * kLineWidth, y + 0.5 * kLineWidth, 0.02,
               white, 1.0f);
  }
  group->addChild(layer(paint, -4.0f, kBinRoadPaint));
  return group;
}

}  // namespace bdfcar::render
