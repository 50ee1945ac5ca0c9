#include "render/gg_diagram.h"

#include <osg/LineWidth>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bdfcar::render {
namespace {

constexpr double kG = 9.80665;        // m/s^2 per g
constexpr double kTrailSeconds = 0.5;  // simulated time the trail covers
constexpr int kRingSegments = 48, kDotSegments = 16;
// Pure, unlit and opaque: no other pixel of the scene has this yellow (the
// render test finds the dot by it).
const osg::Vec4 kDot(1.0f, 0.84f, 0.1f, 1.0f);

// A dynamic geometry of lines or triangles in pixel coordinates, with per-vertex colours.
osg::ref_ptr<osg::Geometry> makeGeometry(GLenum mode) {
  osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
  g->setUseDisplayList(false);
  g->setUseVertexBufferObjects(true);
  g->setDataVariance(osg::Object::DYNAMIC);
  g->setVertexArray(new osg::Vec3Array);
  g->setColorArray(new osg::Vec4Array, osg::Array::BIND_PER_VERTEX);
  g->addPrimitiveSet(new osg::DrawArrays(mode, 0, 0));
  return g;
}

// Replaces a geometry's vertices and colours and draws all of them.
void setVertices(osg::Geometry& g, osg::Vec3Array* v, osg::Vec4Array* c) {
  g.setVertexArray(v);
  g.setColorArray(c, osg::Array::BIND_PER_VERTEX);
  static_cast<osg::DrawArrays*>(g.getPrimitiveSet(0))->setCount(static_cast<GLsizei>(v->size()));
  g.dirtyBound();
}

// The dot's place for an acceleration, in units of the 1 g radius: the
// acceleration seen from above, car pointing up (+ forward up, + left to the left).
osg::Vec2 dotAt(double ax, double ay) {
  osg::Vec2 p(float(-ay / kG), float(ax / kG));
  const float r = p.length();
  if (r > GgDiagram::kClampG) p *= GgDiagram::kClampG / r;
  return p;
}

}  // namespace

GgDiagram::GgDiagram(osgText::Font* font)
    : geode_(new osg::Geode), grid_(makeGeometry(GL_LINES)), trail_(makeGeometry(GL_LINE_STRIP)),
      dot_(makeGeometry(GL_TRIANGLES)), label_(new osgText::Text) {
  trail_->getOrCreateStateSet()->setAttributeAndModes(new osg::LineWidth(3.0f));
  label_->setFont(font);
  label_->setAlignment(osgText::Text::LEFT_BOTTOM);
  label_->setColor(osg::Vec4(1.0f, 1.0f, 1.0f, 0.75f));
  label_->setCharacterSizeMode(osgText::Text::OBJECT_COORDS);
  label_->setText("1 g");
  geode_->addDrawable(grid_.get());
  geode_->addDrawable(label_.get());
  geode_->addDrawable(trail_.get());
  geode_->addDrawable(dot_.get());  // last: on top of the trail
  samples_.push_back({0.0, osg::Vec2()});
}

// Rings at 0.5 and 1 g, axes across them, the ring's label at its upper right.
void GgDiagram::layout(float cx, float cy, float radius, float textSize) {
  cx_ = cx;
  cy_ = cy;
  radius_ = radius;
  osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
  osg::ref_ptr<osg::Vec4Array> c = new osg::Vec4Array;
  auto line = [&](const osg::Vec2& a, const osg::Vec2& b, float alpha) {
    v->push_back(osg::Vec3(cx + radius * a.x(), cy + radius * a.y(), 0));
    v->push_back(osg::Vec3(cx + radius * b.x(), cy + radius * b.y(), 0));
    c->insert(c->end(), 2, osg::Vec4(1, 1, 1, alpha));
  };
  for (float ring : {0.5f, 1.0f}) {
    for (int s = 0; s < kRingSegments; ++s) {
      const double a0 = 2 * std::numbers::pi * s / kRingSegments, a1 = 2 * std::numbers::pi * (s + 1) / kRingSegments;
      line(osg::Vec2(float(std::cos(a0)), float(std::sin(a0))) * ring,
           osg::Vec2(float(std::cos(a1)), float(std::sin(a1))) * ring, ring == 1.0f ? 0.7f : 0.45f);
    }
  }
  line({-kClampG, 0}, {kClampG, 0}, 0.3f);
  line({0, -kClampG}, {0, kClampG}, 0.3f);
  setVertices(*grid_, v.get(), c.get());
  label_->setCharacterSize(textSize);
  const unsigned fontPixels = static_cast<unsigned>(std::lround(textSize));  // one texel per pixel
  label_->setFontResolution(fontPixels, fontPixels);
  label_->setPosition(osg::Vec3(cx + 0.72f * radius, cy + 0.72f * radius, 0));
  redraw();
}

void GgDiagram::update(double time, double ax, double ay) {
  if (time < samples_.back().time) samples_.clear();  // a reset or rewind
  if (!samples_.empty() && time == samples_.back().time) samples_.pop_back();  // the same frame again
  samples_.push_back({time, dotAt(ax, ay)});
  while (samples_.front().time < time - kTrailSeconds) samples_.pop_front();
  redraw();
}

// The trail fades out with its age; the dot is a filled disc at the newest sample.
void GgDiagram::redraw() {
  const double now = samples_.back().time;
  auto pixel = [&](const osg::Vec2& p) { return osg::Vec3(cx_ + radius_ * p.x(), cy_ + radius_ * p.y(), 0); };
  osg::ref_ptr<osg::Vec3Array> tv = new osg::Vec3Array;
  osg::ref_ptr<osg::Vec4Array> tc = new osg::Vec4Array;
  for (const Sample& s : samples_) {
    tv->push_back(pixel(s.at));
    const float fresh = float(1.0 - (now - s.time) / kTrailSeconds);
    tc->push_back(osg::Vec4(kDot.r(), kDot.g(), kDot.b(), 0.6f * fresh));
  }
  setVertices(*trail_, tv.get(), tc.get());

  const osg::Vec3 centre = pixel(samples_.back().at);
  const float r = std::max(3.0f, 0.075f * radius_);
  osg::ref_ptr<osg::Vec3Array> dv = new osg::Vec3Array;
  for (int s = 0; s < kDotSegments; ++s) {
    const double a0 = 2 * std::numbers::pi * s / kDotSegments, a1 = 2 * std::numbers::pi * (s + 1) / kDotSegments;
    dv->push_back(centre);
    dv->push_back(centre + osg::Vec3(float(r * std::cos(a0)), float(r * std::sin(a0)), 0));
    dv->push_back(centre + osg::Vec3(float(r * std::cos(a1)), float(r * std::sin(a1)), 0));
  }
  osg::ref_ptr<osg::Vec4Array> dc = new osg::Vec4Array;
  dc->assign(dv->size(), kDot);
  setVertices(*dot_, dv.get(), dc.get());
}

}  // namespace bdfcar::render
