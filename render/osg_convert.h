// Private to render/: Eigen -> OSG conversions and a small triangle-soup builder.
#pragma once

#include <osg/Geometry>
#include <osg/Matrixd>
#include <osg/Quat>
#include <osg/Vec3d>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vehicle/vehicle_view.h"

namespace bdfcar::render {

inline osg::Vec3d toOsg(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline osg::Vec3 toOsgF(const Eigen::Vector3d& v) { return osg::Vec3(float(v.x()), float(v.y()), float(v.z())); }
inline osg::Quat toOsg(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }
inline osg::Vec4 rgba(double r, double g, double b, double a = 1.0) { return osg::Vec4(float(r), float(g), float(b), float(a)); }

// Model matrix of a body pose (OSG multiplies row vectors: rotate, then translate).
osg::Matrixd poseMatrix(const vehicle::BodyPose& pose);

// Static geometry in buffer objects with per-vertex normals, colours and
// (if uv is given) texture coordinates, drawn as `primitives`.
osg::ref_ptr<osg::Geometry> meshGeometry(osg::Vec3Array* v, osg::Vec3Array* n, osg::Vec4Array* c, osg::Vec2Array* uv,
                                         osg::PrimitiveSet* primitives);

// Accumulates coloured, optionally textured triangles into one osg::Geometry.
struct TriangleBuilder {
  TriangleBuilder();
  // One vertex; texture coordinates only if texcoord() has been enabled.
  void vertex(const osg::Vec3& p, const osg::Vec3& n, const osg::Vec4& colour, const osg::Vec2& uv = {});
  // Flat-shaded triangle (counter-clockwise = front).
  void triangle(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, const osg::Vec4& colour);
  // Flat-shaded quad a b c d (counter-clockwise), as two triangles.
  void quad(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, const osg::Vec3& d, const osg::Vec4& colour);
  void enableTexcoords() { uv = new osg::Vec2Array; }
  osg::ref_ptr<osg::Geometry> build();

  osg::ref_ptr<osg::Vec3Array> v, n;
  osg::ref_ptr<osg::Vec4Array> c;
  osg::ref_ptr<osg::Vec2Array> uv;
};

}  // namespace bdfcar::render
