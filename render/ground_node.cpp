#include <osg/Geode>

#include <array>
#include <vector>

#include "render/nodes.h"
#include "render/osg_convert.h"
#include "render/textures.h"

namespace bdfcar::render {
namespace {

constexpr float kTexelRepeat = 5.0f;  // m per texture repeat
// Fixed-function fog is computed per vertex: a plane drawn as two 4 km
// triangles would be fogged everywhere. Splitting long edges keeps the same
// surface (midpoints of a flat triangle lie on it) with vertices close enough
// for the fog to vary. (Per-pixel fog via GL_FOG_HINT costs seconds per frame on llvmpipe.)
constexpr float kMaxEdge = 120.0f;    // m

struct Corner {
  osg::Vec3 p, n;
};

// Midpoint of two corners, normal renormalised.
Corner midpoint(const Corner& a, const Corner& b) {
  Corner m{(a.p + b.p) * 0.5f, a.n + b.n};
  m.n.normalize();
  return m;
}

// Appends the triangle, halving its longest edge until every edge is at most kMaxEdge.
void addSubdivided(TriangleBuilder& tb, const Corner& a, const Corner& b, const Corner& c) {
  std::vector<std::array<Corner, 3>> stack{{a, b, c}};
  while (!stack.empty()) {
    const std::array<Corner, 3> t = stack.back();
    stack.pop_back();
    int longest = 0;
    float len = 0;
    for (int k = 0; k < 3; ++k) {
      const float l = (t[(k + 1) % 3].p - t[k].p).length();
      if (l > len) {
        len = l;
        longest = k;
      }
    }
    if (len <= kMaxEdge) {
      for (const Corner& q : t)
        tb.vertex(q.p, q.n, osg::Vec4(1, 1, 1, 1), osg::Vec2(q.p.x() / kTexelRepeat, q.p.y() / kTexelRepeat));
      continue;
    }
    // Split edge (longest, longest+1) at its midpoint m; both halves keep the winding.
    const Corner& p0 = t[longest];
    const Corner& p1 = t[(longest + 1) % 3];
    const Corner& p2 = t[(longest + 2) % 3];
    const Corner m = midpoint(p0, p1);
    stack.push_back({p0, m, p2});
    stack.push_back({m, p1, p2});
  }
}

}  // namespace

// The terrain mesh, subdivided for per-vertex fog, textured in world xy so the
// grass scrolls past the car at the true ground speed.
osg::ref_ptr<osg::Node> makeGroundNode(const terrain::TriangleMesh& mesh) {
  TriangleBuilder tb;
  tb.enableTexcoords();
  auto corner = [&](int i) {
    return Corner{toOsgF(mesh.vertices[i]),
                  i < static_cast<int>(mesh.normals.size()) ? toOsgF(mesh.normals[i]) : osg::Vec3(0, 0, 1)};
  };
  for (const auto& t : mesh.triangles) addSubdivided(tb, corner(t[0]), corner(t[1]), corner(t[2]));
  osg::ref_ptr<osg::Geometry> g = tb.build();
  g->getOrCreateStateSet()->setTextureAttributeAndModes(0, grassTexture().get(), osg::StateAttribute::ON);
  g->getOrCreateStateSet()->setRenderBinDetails(kBinGround, "RenderBin");
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(g.get());
  return geode;
}

}  // namespace bdfcar::render
