#include <osg/Geode>

#include <cmath>
#include <numbers>
#include <vector>

#include "render/car_nodes.h"
#include "render/osg_convert.h"

namespace bdfcar::render {
namespace {

constexpr int kSegments = 28;
constexpr int kSpokes = 5;

// Point at angle a (about y) with radial distance r and axial position y.
osg::Vec3 lathe(double a, double r, double y) { return osg::Vec3(float(r * std::cos(a)), float(y), float(r * std::sin(a))); }

// Surface of revolution about y through the (r, y) profile points; smooth normals.
void addRevolved(TriangleBuilder& tb, const std::vector<osg::Vec2>& profile, const osg::Vec4& colour) {
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const osg::Vec2 p0 = profile[k], p1 = profile[k + 1];
    const osg::Vec2 d = p1 - p0;
    for (int s = 0; s < kSegments; ++s) {
      const double a0 = 2 * std::numbers::pi * s / kSegments, a1 = 2 * std::numbers::pi * (s + 1) / kSegments;
      // Normal of the profile segment in the (r, y) plane, turned about y.
      auto normal = [&](double a) {
        osg::Vec3 n = lathe(a, -d.y(), d.x());
        n.normalize();
        return n;
      };
      const osg::Vec3 q[4] = {lathe(a0, p0.x(), p0.y()), lathe(a1, p0.x(), p0.y()), lathe(a1, p1.x(), p1.y()),
                              lathe(a0, p1.x(), p1.y())};
      const osg::Vec3 n[4] = {normal(a0), normal(a1), normal(a1), normal(a0)};
      for (int t : {0, 2, 1, 0, 3, 2}) tb.vertex(q[t], n[t], colour);
    }
  }
}

// Flat ring (annulus) facing +y or -y at axial position y.
void addDisc(TriangleBuilder& tb, double r0, double r1, double y, double facing, const osg::Vec4& colour) {
  for (int s = 0; s < kSegments; ++s) {
    const double a0 = 2 * std::numbers::pi * s / kSegments, a1 = 2 * std::numbers::pi * (s + 1) / kSegments;
    const osg::Vec3 q[4] = {lathe(a0, r0, y), lathe(a1, r0, y), lathe(a1, r1, y), lathe(a0, r1, y)};
    if (facing > 0) tb.quad(q[0], q[1], q[2], q[3], colour);
    else tb.quad(q[0], q[3], q[2], q[1], colour);
  }
}

// Spokes as flat bars at axial position y, so the wheel's spin is visible.
void addSpokes(TriangleBuilder& tb, double rHub, double rRim, double halfWidth, double y, double facing,
               const osg::Vec4& colour) {
  for (int k = 0; k < kSpokes; ++k) {
    const double a = 2 * std::numbers::pi * k / kSpokes, da = halfWidth / rHub, db = halfWidth / rRim;
    const osg::Vec3 q[4] = {lathe(a - da, rHub, y), lathe(a + da, rHub, y), lathe(a + db, rRim, y),
                            lathe(a - db, rRim, y)};
    if (facing > 0) tb.quad(q[0], q[1], q[2], q[3], colour);
    else tb.quad(q[0], q[3], q[2], q[1], colour);
  }
}

}  // namespace

// Tyre with rounded shoulders, recessed dark rim well, silver spokes and hub on both faces.
osg::ref_ptr<osg::Node> makeWheelNode(double radius, double width) {
  const double R = radius, h = 0.5 * width, rimR = 0.68 * R;
  const osg::Vec4 rubber = rgba(0.09, 0.09, 0.1), well = rgba(0.2, 0.2, 0.22), silver = rgba(0.78, 0.79, 0.82),
                  hub = rgba(0.55, 0.56, 0.6);
  TriangleBuilder tb;
  const std::vector<osg::Vec2> tyre = {
      {float(rimR), float(h * 0.92)}, {float(0.9 * R), float(h)},     {float(0.98 * R), float(h * 0.88)},
      {float(R), float(h * 0.6)},     {float(R), float(-h * 0.6)},    {float(0.98 * R), float(-h * 0.88)},
      {float(0.9 * R), float(-h)},    {float(rimR), float(-h * 0.92)}};
  addRevolved(tb, tyre, rubber);
  for (double side : {1.0, -1.0}) {
    const double yWell = side * h * 0.55, ySpoke = side * h * 0.7;
    addDisc(tb, 0.0, rimR, yWell, side, well);
    // Inner face of the rim barrel (normals towards the axle: that face is the one seen).
    const osg::Vec2 lip{float(rimR), float(side * h * 0.92)}, bottom{float(rimR), float(yWell)};
    addRevolved(tb, side > 0 ? std::vector<osg::Vec2>{bottom, lip} : std::vector<osg::Vec2>{lip, bottom}, silver);
    addSpokes(tb, 0.14 * R, rimR, 0.07 * R, ySpoke, side, silver);
    addDisc(tb, 0.0, 0.16 * R, side * h * 0.74, side, hub);
  }
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(tb.build());
  return geode;
}

}  // namespace bdfcar::render
