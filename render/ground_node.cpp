#include <osg/Geode>
#include <osg/PolygonOffset>

#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "render/nodes.h"
#include "render/osg_convert.h"
#include "render/terrain_lod.h"
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

// Appends the triangle to the builder `pick` chooses for it, halving its
// longest edge until every edge is at most kMaxEdge.
template <class Pick>
void addSubdivided(Pick&& pick, const Corner& a, const Corner& b, const Corner& c, const osg::Vec4& colour) {
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
      TriangleBuilder& tb = pick((t[0].p + t[1].p + t[2].p) / 3.0f);
      for (const Corner& q : t)
        tb.vertex(q.p, q.n, colour, osg::Vec2(q.p.x() / kTexelRepeat, q.p.y() / kTexelRepeat));
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

// How each material is drawn: its texture (none: plain colour), the colour
// the texture is modulated by, and its layer. Surfaces laid on the grass
// (pads, tracks) share its plane: a polygon offset and an earlier render bin
// put them on top, paint and curbs on top of those.
enum class Layer { Ground, Surface, Paint, Beneath };
struct Look {
  int texture;  // 0 none, 1 grass, 2 asphalt
  osg::Vec4 colour;
  Layer layer;
};

Look lookOf(terrain::Material m) {
  using terrain::Material;
  switch (m) {
    case Material::Grass: return {1, rgba(1, 1, 1), Layer::Ground};
    case Material::Asphalt: return {2, rgba(1, 1, 1), Layer::Surface};
    case Material::Concrete: return {0, rgba(0.66, 0.65, 0.62), Layer::Surface};
    case Material::Gravel: return {0, rgba(0.6, 0.52, 0.4), Layer::Surface};
    case Material::Paint: return {0, rgba(0.93, 0.93, 0.9), Layer::Paint};
    case Material::CurbRed: return {0, rgba(0.78, 0.1, 0.08), Layer::Paint};
    case Material::CurbWhite: return {0, rgba(0.93, 0.93, 0.9), Layer::Paint};
  }
  return {1, rgba(1, 1, 1), Layer::Ground};
}

}  // namespace

// The terrain mesh, subdivided for per-vertex fog, each material in its own
// geometries; textured in world xy so the surface scrolls past the car at
// the true ground speed. The geometries are tiles of kTile metres, so that
// the view's culling skips what is behind or beside the camera (a proving
// ground's rough road alone is half a million triangles).
osg::ref_ptr<osg::Node> makeGroundNode(const terrain::TriangleMesh& mesh) {
  constexpr float kTile = 100.0f;  // m
  // (texture, layer, tile x, tile y) -> builder; ordered, so the scene graph is the same every time.
  std::map<std::array<int, 4>, TriangleBuilder> builders;
  auto corner = [&](int i) {
    return Corner{toOsgF(mesh.vertices[i]),
                  i < static_cast<int>(mesh.normals.size()) ? toOsgF(mesh.normals[i]) : osg::Vec3(0, 0, 1)};
  };
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    Look look = lookOf(k < mesh.materials.size() ? mesh.materials[k] : terrain::Material::Grass);
    if (k >= mesh.firstBeneath) look.layer = Layer::Beneath;
    auto pick = [&](const osg::Vec3& centre) -> TriangleBuilder& {
      const std::array<int, 4> key{look.texture, static_cast<int>(look.layer),
                                   static_cast<int>(std::floor(centre.x() / kTile)),
                                   static_cast<int>(std::floor(centre.y() / kTile))};
      auto [it, added] = builders.try_emplace(key);
      if (added && look.texture != 0) it->second.enableTexcoords();
      return it->second;
    };
    addSubdivided(pick, corner(t[0]), corner(t[1]), corner(t[2]), look.colour);
  }
  // Stand-ins for dense tiles and for their neighbours of the same look.
  auto levelsFor = [&](const std::array<int, 4>& key) {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const auto it = builders.find({key[0], key[1], key[2] + dx, key[3] + dy});
        if (it != builders.end() && isDense(it->second)) return true;
      }
    return false;
  };
  // Per look with stand-ins, its outline over all its tiles and one table of
  // cluster means for them: their stand-ins meet edge to edge, and meet the
  // other looks on the outline.
  struct Outline {
    LookOutline look;
    std::vector<ClusterMeans> means;
  };
  std::map<std::pair<int, int>, Outline> outlines;
  for (const auto& [key, tb] : builders) {
    if (key[1] == static_cast<int>(Layer::Beneath) || !levelsFor(key) || outlines.count({key[0], key[1]})) continue;
    std::vector<const TriangleBuilder*> tiles, full;
    for (const auto& [other, otherTb] : builders)
      if (other[0] == key[0] && other[1] == key[1]) (levelsFor(other) ? tiles : full).push_back(&otherTb);
    Outline& outline = outlines.try_emplace({key[0], key[1]}, Outline{LookOutline(tiles, full), {}}).first->second;
    std::vector<std::vector<std::uint8_t>> places;
    for (const TriangleBuilder* t : tiles) places.push_back(outline.look.places(*t));
    std::vector<const std::vector<std::uint8_t>*> placesOf;
    for (const auto& p : places) placesOf.push_back(&p);
    outline.means = clusterMeans(tiles, placesOf);
  }
  osg::ref_ptr<osg::Group> tiles = new osg::Group;
  const int bins[4] = {kBinGround, kBinAsphalt, kBinRoadPaint, kBinBeneath};
  const float offsets[4] = {0.0f, -2.0f, -4.0f, 0.0f};
  // One state per (texture, layer), shared by its tiles.
  std::map<std::pair<int, int>, osg::ref_ptr<osg::StateSet>> states;
  for (auto& [key, tb] : builders) {
    const int texture = key[0], layer = key[1];
    osg::ref_ptr<osg::StateSet>& ss = states[{texture, layer}];
    if (!ss) {
      ss = new osg::StateSet;
      if (texture != 0)
        ss->setTextureAttributeAndModes(0, (texture == 1 ? grassTexture() : asphaltTexture()).get(), osg::StateAttribute::ON);
      if (offsets[layer] != 0.0f)
        ss->setAttributeAndModes(new osg::PolygonOffset(-1.0f, offsets[layer]), osg::StateAttribute::ON);
      ss->setRenderBinDetails(bins[layer], "RenderBin");
    }
    const auto outline = outlines.find({texture, layer});
    const bool overAnother = layer == static_cast<int>(Layer::Surface) || layer == static_cast<int>(Layer::Paint);
    if (outline == outlines.end() || !levelsFor(key))
      tiles->addChild(overAnother ? thinnedWithDistance(tb, ss.get(), kTexelRepeat)
                                  : groundTile(tb, ss.get(), kTexelRepeat, nullptr, nullptr, false));
    else
      tiles->addChild(groundTile(tb, ss.get(), kTexelRepeat, &outline->second.look, &outline->second.means, true));
  }
  return tiles;
}

}  // namespace bdfcar::render
