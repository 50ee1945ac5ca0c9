#include "render/track_map.h"

#include <osg/LineWidth>

#include <algorithm>
#include <cmath>

namespace bdfcar::render {

namespace {
const osg::Vec4 kTrack(1.0f, 1.0f, 1.0f, 0.8f);
const osg::Vec4 kCar(1.0f, 0.84f, 0.1f, 1.0f);  // the g-g dot's yellow
constexpr float kMargin = 0.08f;                // of the side, round the line

osg::ref_ptr<osg::Geometry> makeGeometry(GLenum mode, const osg::Vec4& colour) {
  osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
  g->setUseDisplayList(false);
  g->setUseVertexBufferObjects(true);
  g->setDataVariance(osg::Object::DYNAMIC);
  g->setVertexArray(new osg::Vec3Array);
  osg::ref_ptr<osg::Vec4Array> c = new osg::Vec4Array;
  c->push_back(colour);
  g->setColorArray(c.get(), osg::Array::BIND_OVERALL);
  g->addPrimitiveSet(new osg::DrawArrays(mode, 0, 0));
  return g;
}

void setVertices(osg::Geometry& g, osg::Vec3Array* v) {
  g.setVertexArray(v);
  static_cast<osg::DrawArrays*>(g.getPrimitiveSet(0))->setCount(static_cast<GLsizei>(v->size()));
  g.dirtyBound();
}
}  // namespace

TrackMap::TrackMap(const std::vector<Eigen::Vector2d>& line)
    : line_(line), geode_(new osg::Geode), track_(makeGeometry(GL_LINE_LOOP, kTrack)),
      car_(makeGeometry(GL_TRIANGLES, kCar)) {
  Eigen::Vector2d lo = line_.front(), hi = line_.front();
  for (const Eigen::Vector2d& p : line_) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  centre_ = 0.5 * (lo + hi);
  extent_ = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1.0});
  track_->getOrCreateStateSet()->setAttributeAndModes(new osg::LineWidth(2.0f));
  geode_->addDrawable(track_.get());
  geode_->addDrawable(car_.get());  // on top of the line
}

osg::Vec3 TrackMap::toPanel(double x, double y) const {
  const double scale = (1.0 - 2 * kMargin) * side_ / extent_;
  return osg::Vec3(float(x0_ + 0.5 * side_ + scale * (x - centre_.x())),
                   float(y0_ + 0.5 * side_ + scale * (y - centre_.y())), 0.0f);
}

void TrackMap::layout(float x0, float y0, float side) {
  x0_ = x0;
  y0_ = y0;
  side_ = side;
  osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
  for (const Eigen::Vector2d& p : line_) v->push_back(toPanel(p.x(), p.y()));
  setVertices(*track_, v.get());
  update(carX_, carY_, carYaw_);
}

void TrackMap::update(double x, double y, double yaw) {
  carX_ = x;
  carY_ = y;
  carYaw_ = yaw;
  // An arrow a twentieth of the side long, pointing along the heading.
  const osg::Vec3 at = toPanel(x, y);
  const float len = 0.05f * side_;
  const osg::Vec3 ahead(float(std::cos(yaw)), float(std::sin(yaw)), 0), left(-ahead.y(), ahead.x(), 0);
  osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
  v->push_back(at + ahead * len);
  v->push_back(at - ahead * (0.6f * len) + left * (0.5f * len));
  v->push_back(at - ahead * (0.6f * len) - left * (0.5f * len));
  setVertices(*car_, v.get());
}

}  // namespace bdfcar::render
