#include "render/osg_convert.h"

namespace bdfcar::render {

// Rotation then translation of a body pose.
osg::Matrixd poseMatrix(const vehicle::BodyPose& pose) {
  return osg::Matrixd::rotate(toOsg(pose.rotation)) * osg::Matrixd::translate(toOsg(pose.position));
}

TriangleBuilder::TriangleBuilder() : v(new osg::Vec3Array), n(new osg::Vec3Array), c(new osg::Vec4Array) {}

// Appends one vertex with its normal, colour and (optional) texture coordinate.
void TriangleBuilder::vertex(const osg::Vec3& p, const osg::Vec3& normal, const osg::Vec4& colour, const osg::Vec2& t) {
  v->push_back(p);
  n->push_back(normal);
  c->push_back(colour);
  if (uv) uv->push_back(t);
}

// Appends a triangle with its face normal.
void TriangleBuilder::triangle(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& cc, const osg::Vec4& colour) {
  osg::Vec3 normal = (b - a) ^ (cc - a);
  if (normal.normalize() == 0.0f) return;  // degenerate: nothing to see
  vertex(a, normal, colour);
  vertex(b, normal, colour);
  vertex(cc, normal, colour);
}

// Appends a quad as two triangles sharing the diagonal a-c.
void TriangleBuilder::quad(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& cc, const osg::Vec3& d,
                           const osg::Vec4& colour) {
  triangle(a, b, cc, colour);
  triangle(a, cc, d, colour);
}

// Geometry with per-vertex normals and colours drawn as GL_TRIANGLES.
osg::ref_ptr<osg::Geometry> TriangleBuilder::build() {
  return meshGeometry(v.get(), n.get(), c.get(), uv.get(), new osg::DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(v->size())));
}

osg::ref_ptr<osg::Geometry> meshGeometry(osg::Vec3Array* v, osg::Vec3Array* n, osg::Vec4Array* c, osg::Vec2Array* uv,
                                         osg::PrimitiveSet* primitives) {
  osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
  g->setUseDisplayList(false);
  g->setUseVertexBufferObjects(true);
  g->setVertexArray(v);
  g->setNormalArray(n, osg::Array::BIND_PER_VERTEX);
  g->setColorArray(c, osg::Array::BIND_PER_VERTEX);
  if (uv) g->setTexCoordArray(0, uv, osg::Array::BIND_PER_VERTEX);
  g->addPrimitiveSet(primitives);
  return g;
}

}  // namespace bdfcar::render
