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
#include <numbers>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace bdfcar::render {
namespace {

constexpr std::size_t kDenseTriangles = 20000;  // in one tile: above this it gets detail levels
constexpr float kDenseTile = 12.5f;             // m, side of the parts a dense tile is cut into
// A part drawn in full near the camera is cut again, into quarters of this
// side, each switching to the part's first stand-in on its own: only the
// ground next to the camera is drawn in full, not the whole part around it
// (a part's bounding radius, 8.8 m, is more than the distance its stand-in
// needs on a rough road). Only there: small pieces everywhere would cost
// more in draws than they save in triangles (software GL).
constexpr float kNearTile = kDenseTile / 4;
// Below this many triangles a part is not worth cutting again.
constexpr std::size_t kNearSplit = 2000;
// Clustering cells of the stand-ins, m, finest first.
constexpr std::array<float, 3> kCells{0.25f, 1.0f, 4.0f};
// A level is used where its error (clusterTriangles) is under kPixelError
// pixels: an error e at distance d covers e kFocal / d of them (720 lines
// over a 60 deg field: kFocal = 360 / tan 30 deg). A level or evenly sloped
// stretch has none; a centimetre of relief is worth 6 m.
constexpr float kFocal = 623.5f, kPixelError = 1.0f;
// ... and never later than kDistancePerCell cells from its part's bounding
// sphere: seen along the ground from a driver's eye 1.5 m up, a cell there is
// about 5 pixels deep.
constexpr float kDistancePerCell = 30.0f;
// A tile without levels of its own is thinned far away from this many triangles up.
constexpr std::size_t kThinFrom = 256;
// A level worth having removes at least this share of the finer one's triangles.
constexpr double kMinReduction = 0.5;

using Key = std::array<std::uint32_t, 12>;
struct TriangleHash {
  std::size_t operator()(const std::array<GLuint, 3>& t) const {
    return (std::size_t{t[0]} * 73856093u) ^ (std::size_t{t[1]} * 19349663u) ^ (std::size_t{t[2]} * 83492791u);
  }
};

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

std::uint64_t mix(std::uint64_t h, std::uint32_t w) { return (h ^ w) * 1099511628211ull; }
std::uint64_t pointHash(const osg::Vec3& p) {
  return mix(mix(mix(1469598103934665603ull, bits(p.x())), bits(p.y())), bits(p.z()));
}

// An edge of a triangle, as a hash of its two ends' positions (the same for
// both directions).
std::uint64_t edgeKey(const osg::Vec3& a, const osg::Vec3& b) {
  const std::uint64_t ha = pointHash(a), hb = pointHash(b), lo = std::min(ha, hb), hi = std::max(ha, hb);
  return mix(mix(lo, static_cast<std::uint32_t>(hi)), static_cast<std::uint32_t>(hi >> 32));
}

// The column of side `cell` over the xy plane that holds corner k. Columns,
// not cubes: a surface crossing a cube's face in z (a washboard's ridges
// about z = 0) would split into two layers of clusters and tear; a wall (a
// curb's face) becomes a slope at the distances where clusters are used.
Key columnKey(const osg::Vec3& p, float cell) {
  auto index = [&](float x) { return static_cast<std::uint32_t>(static_cast<std::int32_t>(std::floor(x / cell))); };
  return Key{index(p.x()), index(p.y()), 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
}

// Corners merged by key into indexed geometry. Welded (average false), a
// merged vertex is its first corner. Clustered, it takes the mean position and
// colour, the normalised mean normal, and texture coordinates computed from
// the mean position; triangles repeated after the merge are drawn once.
// `error` (clustered): as clusterTriangles says.
template <class KeyOf>
osg::ref_ptr<osg::Geometry> mergeCorners(const TriangleBuilder& tb, KeyOf keyOf, bool average, float texelRepeat,
                                         float cell = 0, float* error = nullptr, const ClusterMeans* shared = nullptr,
                                         const std::vector<std::uint8_t>* places = nullptr) {
  const std::size_t corners = tb.v->size();
  const bool textured = tb.uv && tb.uv->size() == corners;
  std::unordered_map<Key, GLuint, ClusterKeyHash> index;
  std::vector<osg::Vec3> p, n;
  std::vector<osg::Vec4> c;
  std::vector<osg::Vec2> t;
  std::vector<int> count;
  std::vector<Key> column;  // a cluster's column and place (its first corner's), with `shared`
  std::vector<GLuint> of(corners);
  for (std::size_t k = 0; k < corners; ++k) {
    const auto [it, added] = index.try_emplace(keyOf(k), static_cast<GLuint>(p.size()));
    if (added) {
      p.emplace_back(0, 0, 0);
      n.emplace_back(0, 0, 0);
      c.emplace_back(0, 0, 0, 0);
      t.emplace_back(0, 0);
      count.push_back(0);
      if (shared) {  // the cluster's column and place on the outline (a held corner has none: key[11])
        Key col = columnKey((*tb.v)[k], shared->cell);
        col[6] = (*places)[k];
        if ((*places)[k] == kHeld) col[11] = 1;
        column.push_back(col);
      }
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
    if (shared && column[m][11] == 0) {  // the column's mean over the whole look: tiles and parts drawn apart meet
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
  if (error) {
    *error = 0;
    for (std::size_t k = 0; k < corners; ++k) {
      const osg::Vec3 &at = (*v)[of[k]], &normal = (*normals)[of[k]];
      osg::Vec3 own = (*tb.n)[k];
      own.normalize();
      // sin of the angle between them: exact at small angles, where float's acos of a dot is not.
      const float turn = (own ^ normal).length();
      *error = std::max({*error, std::abs(((*tb.v)[k] - at) * normal), cell * turn});
    }
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

// clusterTriangles with the corners' places on the outline (outlinePlaces).
osg::ref_ptr<osg::Geometry> clusterByPlaces(const TriangleBuilder& tb, float cell, float texelRepeat,
                                            const std::vector<std::uint8_t>& place, const ClusterMeans* shared,
                                            float* error) {
  if (shared && shared->cell != cell) shared = nullptr;
  return mergeCorners(
      tb,
      [&](std::size_t k) {
        const osg::Vec3& p = (*tb.v)[k];
        const osg::Vec4& c = (*tb.c)[k];
        if (place[k] == kHeld)  // its own vertex, exactly where it is
          return Key{bits(p.x()), bits(p.y()), bits(p.z()), bits(c.r()), bits(c.g()), bits(c.b()), bits(c.a()), kHeld, 0, 0, 0, 0};
        Key key = columnKey(p, cell);
        key[2] = bits(c.r());
        key[3] = bits(c.g());
        key[4] = bits(c.b());
        key[5] = bits(c.a());
        key[6] = place[k];
        return key;
      },
      true, texelRepeat, cell, error, shared, &place);
}

std::size_t triangleCount(const osg::Geometry& g) { return g.getPrimitiveSet(0)->getNumIndices() / 3; }

osg::ref_ptr<osg::Geode> geodeOf(osg::Geometry* g, osg::StateSet* state) {
  g->setStateSet(state);
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(g);
  return geode;
}

// The builder's triangles in squares of `side` by their centroids, in a fixed order.
std::vector<TriangleBuilder> splitByCentroid(const TriangleBuilder& tb, float side) {
  std::map<std::array<int, 2>, TriangleBuilder> parts;
  const bool textured = tb.uv && tb.uv->size() == tb.v->size();
  for (std::size_t k = 0; k + 2 < tb.v->size(); k += 3) {
    const osg::Vec3 centre = ((*tb.v)[k] + (*tb.v)[k + 1] + (*tb.v)[k + 2]) / 3.0f;
    auto [it, added] = parts.try_emplace({static_cast<int>(std::floor(centre.x() / side)),
                                          static_cast<int>(std::floor(centre.y() / side))});
    if (added && textured) it->second.enableTexcoords();
    for (std::size_t j = k; j < k + 3; ++j)
      it->second.vertex((*tb.v)[j], (*tb.n)[j], (*tb.c)[j], textured ? (*tb.uv)[j] : osg::Vec2());
  }
  std::vector<TriangleBuilder> out;
  for (auto& [cell, part] : parts) out.push_back(std::move(part));
  return out;
}

// Where a part's stand-in of `cell`, with this error, takes over from the
// finer geometry: where its error is under kPixelError or kDistancePerCell
// cells from the part's bounding sphere, whichever is nearer.
float standInFrom(float radius, float cell, float error) {
  return radius + std::min(kDistancePerCell * cell, underAPixelFrom(error));
}

// The part's full geometry as its nearest range draws it: in quarters
// (kNearTile), each in full near the camera and as its own stand-in of
// level `level` (the part's next) from standInFrom on, or whole where
// cutting would not pay.
osg::ref_ptr<osg::Node> nearRange(const TriangleBuilder& part, std::size_t level, osg::StateSet* state,
                                  float texelRepeat, const LookOutline& look, const std::vector<ClusterMeans>& means) {
  if (part.v->size() / 3 < kNearSplit) return geodeOf(weldTriangles(part).get(), state);
  const std::vector<TriangleBuilder> quarters = splitByCentroid(part, kNearTile);
  if (quarters.size() < 2) return geodeOf(weldTriangles(part).get(), state);
  osg::ref_ptr<osg::Group> group = new osg::Group;
  for (const TriangleBuilder& q : quarters) {
    float error = 0;
    osg::ref_ptr<osg::Geometry> coarse =
        clusterByPlaces(q, kCells[level], texelRepeat, look.places(q), &means[level], &error);
    if (error <= 0.0f) {  // nothing lost: the stand-in throughout
      group->addChild(geodeOf(coarse.get(), state));
      continue;
    }
    osg::ref_ptr<osg::Geometry> fine = weldTriangles(q);
    osg::ref_ptr<osg::LOD> lod = new osg::LOD;
    const float switchAt = standInFrom(fine->getBound().radius(), kCells[level], error);
    lod->addChild(geodeOf(fine.get(), state), 0.0f, switchAt);
    lod->addChild(geodeOf(coarse.get(), state), switchAt, std::numeric_limits<float>::max());
    group->addChild(lod);
  }
  return group;
}

// One part: its welded geometry near (nearRange where `cutNearest`, else
// whole), then each stand-in that pays for itself, from standInFrom on (at
// once where it has no error). The full geometry is welded only where it is
// drawn whole (nearRange cuts it).
osg::ref_ptr<osg::Node> partWithLevels(const TriangleBuilder& part, osg::StateSet* state, float texelRepeat,
                                       const LookOutline& look, const std::vector<ClusterMeans>& means,
                                       bool cutNearest = true) {
  osg::ref_ptr<osg::LOD> lod = new osg::LOD;
  osg::BoundingBox box;  // as the welded geometry's bound: the same corners
  for (const osg::Vec3& p : *part.v) box.expandBy(p);
  const float radius = osg::BoundingSphere(box).radius();
  std::size_t triangles = part.v->size() / 3;
  osg::ref_ptr<osg::Geometry> drawn;  // none yet: the full geometry
  const std::vector<std::uint8_t> place = look.places(part);
  float from = 0.0f;
  for (std::size_t level = 0; level < kCells.size(); ++level) {
    const float cell = kCells[level];
    float error = 0;
    osg::ref_ptr<osg::Geometry> coarse = clusterByPlaces(part, cell, texelRepeat, place, &means[level], &error);
    if (double(triangleCount(*coarse)) > (1.0 - kMinReduction) * double(triangles)) continue;
    if (error > 0.0f) {
      const float switchAt = std::max(from, standInFrom(radius, cell, error));
      if (switchAt > from)
        lod->addChild(drawn        ? osg::ref_ptr<osg::Node>(geodeOf(drawn.get(), state))
                      : cutNearest ? nearRange(part, level, state, texelRepeat, look, means)
                                   : osg::ref_ptr<osg::Node>(geodeOf(weldTriangles(part).get(), state)),
                      from, switchAt);
      from = switchAt;
    }
    drawn = coarse;
    triangles = triangleCount(*coarse);
  }
  if (!drawn) drawn = weldTriangles(part);
  lod->addChild(geodeOf(drawn.get(), state), from, std::numeric_limits<float>::max());
  return lod;
}

}  // namespace

float underAPixelFrom(float size) { return size * kFocal / kPixelError; }

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

// An outline edge faces outwards to the right of the counter-clockwise edge
// seen from above. A corner on two that face differently is held.
LookOutline::LookOutline(const std::vector<const TriangleBuilder*>& tiles,
                         const std::vector<const TriangleBuilder*>& drawnInFull) {
  // Every edge by its key, with where it is (tile, first corner, which edge;
  // the tiles drawn in full after the others): sorted, an edge one triangle
  // uses is a run of one.
  struct Edge {
    std::uint64_t key;
    std::uint32_t tile, corner;  // corner: of the triangle's first corner times 3 plus the edge
    bool operator<(const Edge& o) const { return key < o.key; }
  };
  std::vector<const TriangleBuilder*> all = tiles;
  all.insert(all.end(), drawnInFull.begin(), drawnInFull.end());
  std::vector<Edge> edges;
  for (std::size_t t = 0; t < all.size(); ++t) {
    const osg::Vec3Array& v = *all[t]->v;
    for (std::size_t k = 0; k + 2 < v.size(); k += 3)
      for (std::size_t e = 0; e < 3; ++e)
        edges.push_back({edgeKey(v[k + e], v[k + (e + 1) % 3]), static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(k + e)});
  }
  std::sort(edges.begin(), edges.end());
  auto mark = [&](const osg::Vec3& p, std::uint8_t cls) {
    const auto [it, added] = place_.try_emplace(pointHash(p), cls);
    if (!added && it->second != cls) it->second = kHeld;
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const bool alone = (i == 0 || edges[i - 1].key != edges[i].key) && (i + 1 == edges.size() || edges[i + 1].key != edges[i].key);
    if (!alone || edges[i].tile >= tiles.size()) continue;
    const osg::Vec3Array& v = *all[edges[i].tile]->v;
    const std::size_t k = edges[i].corner - edges[i].corner % 3, e = edges[i].corner % 3;
    const osg::Vec3 &a = v[k + e], &b = v[k + (e + 1) % 3];
    const float dx = b.x() - a.x(), dy = b.y() - a.y();
    std::uint8_t cls = kHeld;  // an edge straight up (a wall's) has no direction on the ground
    if (dx * dx + dy * dy > 0.0f) {
      // Eight sectors centred on the axes and diagonals (an edge along an
      // axis lies in the middle of one, never on a border).
      const double angle = std::atan2(-dx, dy);  // of the outward normal (dy, -dx)
      const long sector = std::lround(angle / (std::numbers::pi / 4));
      cls = static_cast<std::uint8_t>(1 + (sector % 8 + 8) % 8);
    }
    mark(a, cls);
    mark(b, cls);
  }
  // A corner the look also draws in full, in a tile without stand-ins, is
  // held: moved, it would open a crack to that tile. So is a corner of a
  // triangle longer than two parts (the plane around the pieces): clustering
  // it saves nothing, and its triangle spans parts drawn at different levels,
  // where a moved corner opens a crack that no bed beneath covers.
  for (const TriangleBuilder* tb : drawnInFull)
    for (const osg::Vec3& p : *tb->v) place_[pointHash(p)] = kHeld;
  for (const TriangleBuilder* tb : tiles) {
    const osg::Vec3Array& v = *tb->v;
    for (std::size_t k = 0; k + 2 < v.size(); k += 3) {
      const float longest = std::max({(v[k + 1] - v[k]).length2(), (v[k + 2] - v[k + 1]).length2(), (v[k] - v[k + 2]).length2()});
      if (longest > 4 * kDenseTile * kDenseTile)
        for (std::size_t j = k; j < k + 3; ++j) place_[pointHash(v[j])] = kHeld;
    }
  }
}

std::vector<std::uint8_t> LookOutline::places(const TriangleBuilder& tb) const {
  std::vector<std::uint8_t> out(tb.v->size(), kInside);
  for (std::size_t k = 0; k < out.size(); ++k)
    if (const auto it = place_.find(pointHash((*tb.v)[k])); it != place_.end()) out[k] = it->second;
  return out;
}

void ClusterMeans::add(const TriangleBuilder& tb, const std::vector<std::uint8_t>& places) {
  for (std::size_t k = 0; k < tb.v->size(); ++k) {
    if (places[k] == kHeld) continue;
    Key key = columnKey((*tb.v)[k], cell);
    key[6] = places[k];
    Sum& sum = sums[key];
    sum.p += (*tb.v)[k];
    sum.n += (*tb.n)[k];
    ++sum.count;
  }
}

std::vector<ClusterMeans> clusterMeans(const std::vector<const TriangleBuilder*>& builders,
                                       const std::vector<const std::vector<std::uint8_t>*>& places) {
  std::vector<ClusterMeans> means;
  for (float cell : kCells) {
    ClusterMeans& m = means.emplace_back();
    m.cell = cell;
    for (std::size_t b = 0; b < builders.size(); ++b) m.add(*builders[b], *places[b]);
  }
  return means;
}

osg::ref_ptr<osg::Geometry> clusterTriangles(const TriangleBuilder& tb, float cell, float texelRepeat,
                                             const std::vector<std::uint8_t>* places, const ClusterMeans* shared,
                                             float* error) {
  if (places) return clusterByPlaces(tb, cell, texelRepeat, *places, shared, error);
  return clusterByPlaces(tb, cell, texelRepeat, LookOutline({&tb}).places(tb), shared, error);
}

bool isDense(const TriangleBuilder& tb) { return tb.v->size() / 3 > kDenseTriangles; }

osg::ref_ptr<osg::Node> thinnedWithDistance(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat) {
  if (tb.v->size() / 3 < kThinFrom) return geodeOf(weldTriangles(tb).get(), state);
  const LookOutline own({&tb});
  const std::vector<std::uint8_t> places = own.places(tb);
  return partWithLevels(tb, state, texelRepeat, own, clusterMeans({&tb}, {&places}), /*cutNearest=*/false);
}

osg::ref_ptr<osg::Node> groundTile(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat,
                                   const LookOutline* look, const std::vector<ClusterMeans>* means, bool levels) {
  if (!levels) return geodeOf(weldTriangles(tb).get(), state);
  std::optional<LookOutline> own;
  if (!look) look = &own.emplace(std::vector<const TriangleBuilder*>{&tb});
  std::vector<ClusterMeans> ownMeans;
  if (!means) {
    const std::vector<std::uint8_t> places = look->places(tb);
    ownMeans = clusterMeans({&tb}, {&places});
    means = &ownMeans;
  }
  osg::ref_ptr<osg::Group> group = new osg::Group;
  for (const TriangleBuilder& part : splitByCentroid(tb, kDenseTile))
    group->addChild(partWithLevels(part, state, texelRepeat, *look, *means));
  return group;
}

}  // namespace bdfcar::render
