#include <osg/Geode>

#include <cmath>
#include <numbers>

#include "render/car_nodes.h"
#include "render/osg_convert.h"

namespace bdfcar::render {
namespace {

constexpr int kKinds = 6;  // LinkKind values

// Distinct colour per member kind, bright against the body paint.
osg::Vec4 linkColour(vehicle::LinkKind kind) {
  switch (kind) {
    case vehicle::LinkKind::Arm: return rgba(0.25, 0.55, 0.95);
    case vehicle::LinkKind::Strut: return rgba(0.98, 0.82, 0.1);
    case vehicle::LinkKind::TieRod: return rgba(0.2, 0.85, 0.3);
    case vehicle::LinkKind::Link: return rgba(0.55, 0.9, 0.95);
    case vehicle::LinkKind::Rack: return rgba(0.85, 0.35, 0.85);
    case vehicle::LinkKind::Spring: return rgba(1.0, 0.45, 0.2);
  }
  return rgba(0.8, 0.8, 0.8);
}

// Closed cylinder of radius 1 from z = 0 to z = 1.
osg::ref_ptr<osg::Node> unitCylinder(const osg::Vec4& colour) {
  constexpr int kSides = 10;
  TriangleBuilder tb;
  for (int s = 0; s < kSides; ++s) {
    const double a0 = 2 * std::numbers::pi * s / kSides, a1 = 2 * std::numbers::pi * (s + 1) / kSides;
    const osg::Vec3 n0(float(std::cos(a0)), float(std::sin(a0)), 0), n1(float(std::cos(a1)), float(std::sin(a1)), 0);
    const osg::Vec3 z(0, 0, 1);
    const osg::Vec3 q[4] = {n0, n1, n1 + z, n0 + z};
    const osg::Vec3 qn[4] = {n0, n1, n1, n0};
    for (int t : {0, 1, 2, 0, 2, 3}) tb.vertex(q[t], qn[t], colour);
    tb.triangle(z, n0 + z, n1 + z, colour);
    tb.triangle(osg::Vec3(), n1, n0, colour);
  }
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(tb.build());
  return geode;
}

}  // namespace

LinkPool::LinkPool() : group_(new osg::Group) {
  // Non-uniform scaling of the unit cylinder: normals must be renormalised.
  group_->getOrCreateStateSet()->setMode(GL_NORMALIZE, osg::StateAttribute::ON);
  for (int k = 0; k < kKinds; ++k) unitCylinders_.push_back(unitCylinder(linkColour(static_cast<vehicle::LinkKind>(k))));
}

// Scales, turns and moves one unit cylinder onto each segment a -> b.
void LinkPool::update(const std::vector<vehicle::LinkSegment>& links) {
  while (pool_.size() < links.size()) {
    pool_.push_back(new osg::MatrixTransform);
    group_->addChild(pool_.back());
  }
  for (std::size_t i = 0; i < pool_.size(); ++i) {
    osg::MatrixTransform& t = *pool_[i];
    if (i >= links.size()) {
      t.setNodeMask(0);
      continue;
    }
    const vehicle::LinkSegment& s = links[i];
    const osg::Vec3d a = toOsg(s.a), d = toOsg(s.b) - a;
    const double length = d.length();
    t.setNodeMask(length > 1e-6 ? ~0u : 0u);
    if (length <= 1e-6) continue;
    osg::Quat turn;
    turn.makeRotate(osg::Vec3d(0, 0, 1), d / length);
    t.setMatrix(osg::Matrixd::scale(s.radius, s.radius, length) * osg::Matrixd::rotate(turn) * osg::Matrixd::translate(a));
    osg::Node* shape = unitCylinders_[static_cast<int>(s.kind) % kKinds].get();
    if (t.getNumChildren() != 1 || t.getChild(0) != shape) {
      t.removeChildren(0, t.getNumChildren());
      t.addChild(shape);
    }
  }
}

}  // namespace bdfcar::render
