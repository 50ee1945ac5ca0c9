#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/PolygonOffset>

#include <cmath>
#include <numbers>

#include "render/nodes.h"
#include "render/osg_convert.h"

namespace bdfcar::render {

// Radial fan fading from dark at the centre to transparent at the rim.
osg::ref_ptr<osg::Node> makeShadowNode(double length, double width) {
  constexpr int kSegments = 24;
  TriangleBuilder tb;
  const osg::Vec3 up(0, 0, 1);
  const osg::Vec4 dark = rgba(0, 0, 0, 0.55), clear = rgba(0, 0, 0, 0);
  for (int s = 0; s < kSegments; ++s) {
    const double a0 = 2 * std::numbers::pi * s / kSegments, a1 = 2 * std::numbers::pi * (s + 1) / kSegments;
    auto rim = [&](double a) {
      return osg::Vec3(float(0.5 * length * std::cos(a)), float(0.5 * width * std::sin(a)), 0.0f);
    };
    tb.vertex(osg::Vec3(0, 0, 0), up, dark);
    tb.vertex(rim(a0), up, clear);
    tb.vertex(rim(a1), up, clear);
  }
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(tb.build());
  osg::StateSet* ss = geode->getOrCreateStateSet();
  ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
  ss->setMode(GL_BLEND, osg::StateAttribute::ON);
  ss->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
  ss->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
  ss->setAttributeAndModes(new osg::PolygonOffset(-1.0f, -6.0f));
  ss->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
  return geode;
}

}  // namespace bdfcar::render
