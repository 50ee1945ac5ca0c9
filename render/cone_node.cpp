#include <osg/Geode>
#include <osg/LOD>
#include <osg/PositionAttitudeTransform>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "render/nodes.h"
#include "render/osg_convert.h"
#include "render/terrain_lod.h"

namespace bdfcar::render {
namespace {

constexpr double kBase = 0.03, kTop = 0.5, kR0 = 0.15, kR1 = 0.025;

// One traffic cone (0.5 m, orange with a white band) on a black square base,
// origin at ground level, its body a pyramid of `sides` sides.
osg::ref_ptr<osg::Geode> makeConeGeode(int sides) {
  const osg::Vec4 orange = rgba(1.0, 0.36, 0.02), white = rgba(0.95, 0.95, 0.95), black = rgba(0.08, 0.08, 0.08);
  TriangleBuilder tb;
  // Base plate: a low box.
  const float b = 0.18f, h = float(kBase);
  const osg::Vec3 c[8] = {{-b, -b, 0}, {b, -b, 0}, {b, b, 0}, {-b, b, 0}, {-b, -b, h}, {b, -b, h}, {b, b, h}, {-b, b, h}};
  tb.quad(c[4], c[5], c[6], c[7], black);
  tb.quad(c[0], c[1], c[5], c[4], black);
  tb.quad(c[1], c[2], c[6], c[5], black);
  tb.quad(c[2], c[3], c[7], c[6], black);
  tb.quad(c[3], c[0], c[4], c[7], black);
  // Body in three bands so the white band has sharp edges; smooth normals around.
  const double bands[4] = {0.0, 0.42, 0.62, 1.0};  // fraction of the body height
  const double slope = (kR0 - kR1) / (kTop - kBase);
  for (int k = 0; k < 3; ++k) {
    const osg::Vec4 colour = (k == 1) ? white : orange;
    const double z0 = kBase + bands[k] * (kTop - kBase), z1 = kBase + bands[k + 1] * (kTop - kBase);
    const double r0 = kR0 - slope * (z0 - kBase), r1 = kR0 - slope * (z1 - kBase);
    for (int s = 0; s < sides; ++s) {
      const double a0 = 2 * std::numbers::pi * s / sides, a1 = 2 * std::numbers::pi * (s + 1) / sides;
      auto p = [](double a, double r, double z) { return osg::Vec3(float(r * std::cos(a)), float(r * std::sin(a)), float(z)); };
      auto nrm = [&](double a) {
        osg::Vec3 n(float(std::cos(a)), float(std::sin(a)), float(slope));
        n.normalize();
        return n;
      };
      const osg::Vec3 q[4] = {p(a0, r0, z0), p(a1, r0, z0), p(a1, r1, z1), p(a0, r1, z1)};
      const osg::Vec3 qn[4] = {nrm(a0), nrm(a1), nrm(a1), nrm(a0)};
      for (int t : {0, 1, 2, 0, 2, 3}) tb.vertex(q[t], qn[t], colour);
    }
  }
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(tb.build());
  return geode;
}

// A cone with fewer sides farther out: a pyramid of n sides inside the
// round cone falls short of its outline by r (1 - cos(pi / n)) at most,
// drawn from where that is under a pixel (16 sides next to the camera; a
// course's far cones are 100 triangles each where a few pixels show them).
osg::ref_ptr<osg::LOD> makeConeLevels() {
  osg::ref_ptr<osg::LOD> lod = new osg::LOD;
  constexpr std::array<int, 3> kSides{16, 6, 3};
  float from = 0.0f;
  for (std::size_t k = 0; k < kSides.size(); ++k) {
    osg::ref_ptr<osg::Geode> geode = makeConeGeode(kSides[k]);
    const float to = k + 1 < kSides.size()
                         ? geode->getBound().radius() +
                               underAPixelFrom(float(kR0 * (1.0 - std::cos(std::numbers::pi / kSides[k + 1]))))
                         : std::numeric_limits<float>::max();
    lod->addChild(geode, from, to);
    from = to;
  }
  return lod;
}

}  // namespace

// The same cone geometry instanced at every course position.
osg::ref_ptr<osg::Group> makeConesNode(const std::vector<Eigen::Vector3d>& cones, const SurfaceSampler& ground) {
  osg::ref_ptr<osg::Group> group = new osg::Group;
  if (cones.empty()) return group;
  osg::ref_ptr<osg::LOD> cone = makeConeLevels();
  for (const Eigen::Vector3d& p : cones) {
    osg::ref_ptr<osg::PositionAttitudeTransform> t = new osg::PositionAttitudeTransform;
    t->setPosition(osg::Vec3d(p.x(), p.y(), ground.heightOr(p.x(), p.y(), p.z()) + 0.01));
    t->addChild(cone);
    group->addChild(t);
  }
  return group;
}

void knockCone(osg::Group& cones, int index, double heading) {
  if (index < 0 || index >= static_cast<int>(cones.getNumChildren())) return;
  auto* t = static_cast<osg::PositionAttitudeTransform*>(cones.getChild(index));
  // Tipped about its base's edge by 80 deg (it rests on its base rim and
  // tip), about the horizontal axis across the direction it was pushed.
  const osg::Vec3d push(std::cos(heading), std::sin(heading), 0.0), axis = osg::Vec3d(0, 0, 1) ^ push;
  t->setAttitude(osg::Quat(osg::DegreesToRadians(80.0), axis));
  t->setPivotPoint(osg::Vec3d(0, 0, 0));
}

}  // namespace bdfcar::render
