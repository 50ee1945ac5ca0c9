#include "render/terrain_lod.h"

#include <osg/Geode>
#include <osg/LOD>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace bdfcar::render {
namespace {

constexpr std::size_t kDenseTriangles = 20000;  // in one tile: above this it gets detail levels
constexpr float kDenseTile = 12.5f;             // m, side of the parts a dense tile is cut into
// Clustering cells of the stand-ins, m, finest first. A level is used beyond
// kDistancePerCell cells from its part's bounding sphere. Seen along the ground
// from a driver's eye 1.5 m up (720 lines, 60 deg), a cell there is about 5
// pixels deep, and a centimetre of relief under a pixel high. (At 120 cells,
// a cell 3 pixels across, the rough road drew at 45 ms a frame on llvmpipe
// and 28 ms at 30, with parts of 12.5 m instead of 25.)
constexpr std::array<float, 3> kCells{0.25f, 1.0f, 4.0f};
constexpr float kDistancePerCell = 30.0f;
// A level worth having removes at least this share of the finer one's triangles.
constexpr double kMinReduction = 0.5;

using Key = std::array<std::uint32_t, 12>;
struct TriangleHash {
  std::size_t operator()(const std::array<GLuint, 3>& t) const {
    return (std::size_t{t[0]} * 73856093u) ^ (std::size_t{t[1]} * 19349663u) ^ (std::size_t{t[2]} * 83492791u);
  }
};

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

// The column of side `cell` over the xy plane that holds corner k. Columns,
// not cubes: a surface crossing a cube's face in z (a washboard's ridges
// about z = 0) would split into two layers of clusters and tear; a wall (a
// curb's face) becomes a slope at the distances where clusters are used.
Key columnKey(const osg::Vec3& p, float cell) {
  auto index = [&](float x) { return static_cast<std::uint32_t>(static_cast<std::int32_t>(std::floor(x / cell))); };
  return Key{index(p.x()), index(p.y()), 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
}

// The cluster of corner k: its column and its colour.
Key clusterKey(const TriangleBuilder& tb, std::size_t k, float cell) {
  Key key = columnKey((*tb.v)[k], cell);
  const osg::Vec4& c = (*tb.c)[k];
  key[2] = bits(c.r());
  key[3] = bits(c.g());
  key[4] = bits(c.b());
  key[5] = bits(c.a());
  return key;
}

// Corners merged by key into indexed geometry. Welded (average false), a
// merged vertex is its first corner. Clustered, it takes the mean position and
// colour, the normalised mean normal, and texture coordinates computed from
// the mean position; triangles repeated after the merge are drawn once.
template <class KeyOf>
osg::ref_ptr<osg::Geometry> mergeCorners(const TriangleBuilder& tb, KeyOf keyOf, bool average, float texelRepeat,
                                         const ClusterMeans* shared = nullptr) {
  const std::size_t corners = tb.v->size();
  const bool textured = tb.uv && tb.uv->size() == corners;
  std::unordered_map<Key, GLuint, ClusterKeyHash> index;
  std::vector<osg::Vec3> p, n;
  std::vector<osg::Vec4> c;
  std::vector<osg::Vec2> t;
  std::vector<int> count;
  std::vector<Key> column;  // a cluster's column (its first corner's)
  std::vector<GLuint> of(corners);
  for (std::size_t k = 0; k < corners; ++k) {
    const auto [it, added] = index.try_emplace(keyOf(k), static_cast<GLuint>(p.size()));
    if (added) {
      p.emplace_back(0, 0, 0);
      n.emplace_back(0, 0, 0);
      c.emplace_back(0, 0, 0, 0);
      t.emplace_back(0, 0);
      count.push_back(0);
      if (shared) column.push_back(columnKey((*tb.v)[k], shared->cell));
    }
    const GLuint m = it->second;
    of[k] = m;
    if (!average && !added) continue;  // welded: the first corner's values, exactly
    p[m] += (*tb.v)[k];
    n[m] += (*tb.n)[k];
    c[m] += (*tb.c)[k];
    if (textured) t[m] += (*tb.uv)[k];
    ++count[m];
  }

  osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array, normals = new osg::Vec3Array;
  osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
  osg::ref_ptr<osg::Vec2Array> uv = textured ? new osg::Vec2Array : nullptr;
  for (std::size_t m = 0; m < p.size(); ++m) {
    const float w = average ? 1.0f / float(count[m]) : 1.0f;
    osg::Vec3 at = p[m] * w;
    osg::Vec3 normal = n[m];
    if (shared) {  // the column's mean over the whole ground: tiles and parts drawn apart meet edge to edge
      const ClusterMeans::Sum& sum = shared->sums.at(column[m]);
      at = sum.p / float(sum.count);
      normal = sum.n;
    }
    if (average && normal.normalize() == 0.0f) normal = osg::Vec3(0, 0, 1);
    v->push_back(at);
    normals->push_back(normal);
    colours->push_back(c[m] * w);
    if (uv) uv->push_back(average ? osg::Vec2(at.x() / texelRepeat, at.y() / texelRepeat) : t[m]);
  }
  osg::ref_ptr<osg::DrawElementsUInt> triangles = new osg::DrawElementsUInt(GL_TRIANGLES);
  std::unordered_set<std::array<GLuint, 3>, TriangleHash> seen;
  for (std::size_t k = 0; k + 2 < corners; k += 3) {
    const std::array<GLuint, 3> tri{of[k], of[k + 1], of[k + 2]};
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;  // collapsed
    if (average) {
      // The same three vertices in the same turn are one triangle drawn twice.
      const std::size_t first = std::min_element(tri.begin(), tri.end()) - tri.begin();
      const std::array<GLuint, 3> canonical{tri[first], tri[(first + 1) % 3], tri[(first + 2) % 3]};
      if (!seen.insert(canonical).second) continue;
    }
    triangles->insert(triangles->end(), tri.begin(), tri.end());
  }

  return meshGeometry(v.get(), normals.get(), colours.get(), uv.get(), triangles.get());
}

std::size_t triangleCount(const osg::Geometry& g) { return g.getPrimitiveSet(0)->getNumIndices() / 3; }

osg::ref_ptr<osg::Geode> geodeOf(osg::Geometry* g, osg::StateSet* state) {
  g->setStateSet(state);
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(g);
  return geode;
}

// The builder's triangles in parts of kDenseTile by their centroids, in a fixed order.
std::vector<TriangleBuilder> splitByCentroid(const TriangleBuilder& tb) {
  std::map<std::array<int, 2>, TriangleBuilder> parts;
  const bool textured = tb.uv && tb.uv->size() == tb.v->size();
  for (std::size_t k = 0; k + 2 < tb.v->size(); k += 3) {
    const osg::Vec3 centre = ((*tb.v)[k] + (*tb.v)[k + 1] + (*tb.v)[k + 2]) / 3.0f;
    auto [it, added] = parts.try_emplace({static_cast<int>(std::floor(centre.x() / kDenseTile)),
                                          static_cast<int>(std::floor(centre.y() / kDenseTile))});
    if (added && textured) it->second.enableTexcoords();
    for (std::size_t j = k; j < k + 3; ++j)
      it->second.vertex((*tb.v)[j], (*tb.n)[j], (*tb.c)[j], textured ? (*tb.uv)[j] : osg::Vec2());
  }
  std::vector<TriangleBuilder> out;
  for (auto& [cell, part] : parts) out.push_back(std::move(part));
  return out;
}

// One part: its welded geometry near, then each stand-in that pays for itself.
osg::ref_ptr<osg::Node> partWithLevels(const TriangleBuilder& part, osg::StateSet* state, float texelRepeat,
                                       const std::vector<ClusterMeans>& means) {
  osg::ref_ptr<osg::Geometry> full = weldTriangles(part);
  osg::ref_ptr<osg::LOD> lod = new osg::LOD;
  const float radius = full->getBound().radius();
  std::size_t triangles = triangleCount(*full);
  osg::ref_ptr<osg::Geometry> drawn = full;
  float from = 0.0f;
  for (std::size_t level = 0; level < kCells.size(); ++level) {
    const float cell = kCells[level];
    osg::ref_ptr<osg::Geometry> coarse = clusterTriangles(part, cell, texelRepeat, &means[level]);
    if (double(triangleCount(*coarse)) > (1.0 - kMinReduction) * double(triangles)) continue;
    const float switchAt = radius + kDistancePerCell * cell;
    lod->addChild(geodeOf(drawn.get(), state), from, switchAt);
    drawn = coarse;
    triangles = triangleCount(*coarse);
    from = switchAt;
  }
  lod->addChild(geodeOf(drawn.get(), state), from, std::numeric_limits<float>::max());
  return lod;
}

}  // namespace

osg::ref_ptr<osg::Geometry> weldTriangles(const TriangleBuilder& tb) {
  const bool textured = tb.uv && tb.uv->size() == tb.v->size();
  return mergeCorners(
      tb,
      [&](std::size_t k) {
        const osg::Vec3 &p = (*tb.v)[k], &n = (*tb.n)[k];
        const osg::Vec4& c = (*tb.c)[k];
        const osg::Vec2 t = textured ? (*tb.uv)[k] : osg::Vec2();
        return Key{bits(p.x()), bits(p.y()), bits(p.z()), bits(n.x()), bits(n.y()), bits(n.z()),
                   bits(c.r()),  bits(c.g()), bits(c.b()), bits(c.a()), bits(t.x()), bits(t.y())};
      },
      false, 0.0f);
}

void ClusterMeans::add(const TriangleBuilder& tb) {
  for (std::size_t k = 0; k < tb.v->size(); ++k) {
    Sum& sum = sums[columnKey((*tb.v)[k], cell)];
    sum.p += (*tb.v)[k];
    sum.n += (*tb.n)[k];
    ++sum.count;
  }
}

std::vector<ClusterMeans> clusterMeans(const std::vector<const TriangleBuilder*>& builders) {
  std::vector<ClusterMeans> means;
  for (float cell : kCells) {
    ClusterMeans& m = means.emplace_back();
    m.cell = cell;
    for (const TriangleBuilder* tb : builders) m.add(*tb);
  }
  return means;
}

osg::ref_ptr<osg::Geometry> clusterTriangles(const TriangleBuilder& tb, float cell, float texelRepeat,
                                             const ClusterMeans* shared) {
  if (shared && shared->cell != cell) shared = nullptr;
  return mergeCorners(tb, [&](std::size_t k) { return clusterKey(tb, k, cell); }, true, texelRepeat, shared);
}

bool isDense(const TriangleBuilder& tb) { return tb.v->size() / 3 > kDenseTriangles; }

osg::ref_ptr<osg::Node> groundTile(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat,
                                   const std::vector<ClusterMeans>* means, bool levels) {
  if (!levels) return geodeOf(weldTriangles(tb).get(), state);
  const std::vector<ClusterMeans> own = means ? std::vector<ClusterMeans>{} : clusterMeans({&tb});
  if (!means) means = &own;
  osg::ref_ptr<osg::Group> group = new osg::Group;
  for (const TriangleBuilder& part : splitByCentroid(tb))
    group->addChild(partWithLevels(part, state, texelRepeat, *means));
  return group;
}

}  // namespace bdfcar::render
