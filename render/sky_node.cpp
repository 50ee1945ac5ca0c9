#include <osg/Depth>
#include <osg/Geode>

#include <cmath>
#include <numbers>

#include "render/nodes.h"
#include "render/osg_convert.h"

namespace bdfcar::render {

// Latitude-longitude dome coloured by elevation: horizon haze to zenith blue,
// continued below the horizon so a pitched camera never sees the clear colour.
osg::ref_ptr<osg::MatrixTransform> makeSkyDome() {
  constexpr int kSlices = 24, kStacks = 8;
  constexpr double kRadius = 1000.0;
  const osg::Vec4 below(0.55f, 0.62f, 0.55f, 1.0f);
  auto colourAt = [&](double elevation) {
    if (elevation < 0) return kSkyHorizon * 0.7f + below * 0.3f;
    const float s = float(std::pow(std::sin(elevation), 0.6));
    return kSkyHorizon * (1 - s) + kSkyZenith * s;
  };
  TriangleBuilder tb;
  const double pi = std::numbers::pi;
  for (int k = -1; k < kStacks; ++k) {
    const double e0 = k * (pi / 2) / kStacks, e1 = (k + 1) * (pi / 2) / kStacks;
    for (int s = 0; s < kSlices; ++s) {
      const double a0 = 2 * pi * s / kSlices, a1 = 2 * pi * (s + 1) / kSlices;
      auto p = [&](double a, double e) {
        return osg::Vec3(float(kRadius * std::cos(e) * std::cos(a)), float(kRadius * std::cos(e) * std::sin(a)),
                         float(kRadius * std::sin(e)));
      };
      // Inward-facing quad; every vertex gets the colour of its own elevation.
      const osg::Vec3 q[4] = {p(a0, e0), p(a0, e1), p(a1, e1), p(a1, e0)};
      const double el[4] = {e0, e1, e1, e0};
      for (int t : {0, 1, 2, 0, 2, 3}) tb.vertex(q[t], -q[t] / float(kRadius), colourAt(el[t]));
    }
  }
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(tb.build());
  osg::StateSet* ss = geode->getOrCreateStateSet();
  ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
  ss->setMode(GL_FOG, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
  ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
  // Drawn after the opaque world, squashed onto the far plane: it only fills
  // pixels nothing else covered, so it costs no overdraw.
  ss->setAttributeAndModes(new osg::Depth(osg::Depth::LEQUAL, 1.0, 1.0, false));
  ss->setRenderBinDetails(kBinSky, "RenderBin");
  osg::ref_ptr<osg::MatrixTransform> t = new osg::MatrixTransform;
  t->setCullingActive(false);
  t->addChild(geode);
  return t;
}

}  // namespace bdfcar::render
