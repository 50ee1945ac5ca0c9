// The ground's levels of detail (render/terrain_lod): welding changes no
// corner, clustering keeps a surface where it was and the area it covers,
// and a dense tile gets coarser levels farther out; road paint and cones
// thin with distance by under a pixel. No GL context needed.
#include <gtest/gtest.h>

#include <osg/Geode>
#include <osg/LOD>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "render/nodes.h"
#include "render/surface_sampler.h"
#include "render/terrain_lod.h"
#include "render/terrain_surface.h"
#include "terrain/terrain_file.h"
#include "terrain/terrain_mesh.h"
#include "test_files.h"

using namespace bdfcar::render;

namespace {

constexpr float kRepeat = 5.0f;  // m per texture repeat, as the ground's

// z of a gently rolling test surface.
float heightAt(float x, float y) { return 0.05f * std::sin(1.3f * x) * std::cos(0.7f * y); }

// A grid of n x n cells of side h from (x0, y0), two triangles a cell, corners
// with the surface's height, an up normal and world-xy texture coordinates,
// written one corner per triangle as the ground's builder writes them.
TriangleBuilder grid(int n, float h, float x0 = 0, float y0 = 0, bool flat = false) {
  TriangleBuilder tb;
  tb.enableTexcoords();
  auto corner = [&](int i, int j) {
    const float x = x0 + i * h, y = y0 + j * h;
    const osg::Vec3 p(x, y, flat ? 0.0f : heightAt(x, y));
    tb.vertex(p, osg::Vec3(0, 0, 1), osg::Vec4(1, 1, 1, 1), osg::Vec2(x / kRepeat, y / kRepeat));
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      corner(i, j), corner(i + 1, j), corner(i + 1, j + 1);
      corner(i, j), corner(i + 1, j + 1), corner(i, j + 1);
    }
  return tb;
}

const osg::Vec3Array& vertices(const osg::Geometry& g) { return *static_cast<const osg::Vec3Array*>(g.getVertexArray()); }
const osg::DrawElementsUInt& indices(const osg::Geometry& g) {
  return *static_cast<const osg::DrawElementsUInt*>(g.getPrimitiveSet(0));
}

// Area of the geometry's triangles projected on the xy plane (all face up here).
double projectedArea(const osg::Geometry& g) {
  const auto& v = vertices(g);
  const auto& e = indices(g);
  double area = 0;
  for (std::size_t k = 0; k + 2 < e.size(); k += 3) {
    const osg::Vec3 a = v[e[k]], b = v[e[k + 1]], c = v[e[k + 2]];
    area += 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
  }
  return area;
}

// Of the points (x, y), the share covered by no triangle of the geometries.
double uncovered(const std::vector<const osg::Geometry*>& gs, const std::vector<osg::Vec2>& points) {
  std::map<int, std::vector<std::array<osg::Vec3, 3>>> byMetre;  // triangles by the whole metres of x they span
  for (const osg::Geometry* g : gs) {
    const auto& v = vertices(*g);
    const auto& e = indices(*g);
    for (std::size_t k = 0; k + 2 < e.size(); k += 3) {
      const std::array<osg::Vec3, 3> t{v[e[k]], v[e[k + 1]], v[e[k + 2]]};
      const float lo = std::min({t[0].x(), t[1].x(), t[2].x()}), hi = std::max({t[0].x(), t[1].x(), t[2].x()});
      for (int m = int(std::floor(lo)); m <= int(std::floor(hi)); ++m) byMetre[m].push_back(t);
    }
  }
  auto inside = [](const std::array<osg::Vec3, 3>& t, const osg::Vec2& q) {
    auto side = [&](const osg::Vec3& a, const osg::Vec3& b) {
      return (b.x() - a.x()) * (q.y() - a.y()) - (b.y() - a.y()) * (q.x() - a.x());
    };
    const float s0 = side(t[0], t[1]), s1 = side(t[1], t[2]), s2 = side(t[2], t[0]);
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
  };
  int missed = 0;
  for (const osg::Vec2& q : points) {
    bool hit = false;
    for (const auto& t : byMetre[int(std::floor(q.x()))])
      if ((hit = inside(t, q))) break;
    missed += !hit;
  }
  return double(missed) / double(points.size());
}

// The geometries a node draws at distance d from the camera (an LOD's child
// whose range holds d; a group's children all).
void drawnAt(const osg::Node* node, float d, std::vector<const osg::Geometry*>& out) {
  if (const auto* lod = dynamic_cast<const osg::LOD*>(node)) {
    for (unsigned k = 0; k < lod->getNumChildren(); ++k)
      if (d >= lod->getMinRange(k) && d < lod->getMaxRange(k)) drawnAt(lod->getChild(k), d, out);
  } else if (const osg::Geode* geode = node->asGeode()) {
    for (unsigned k = 0; k < geode->getNumDrawables(); ++k) out.push_back(geode->getDrawable(k)->asGeometry());
  } else if (const osg::Group* group = node->asGroup()) {
    for (unsigned k = 0; k < group->getNumChildren(); ++k) drawnAt(group->getChild(k), d, out);
  }
}

std::size_t triangles(const std::vector<const osg::Geometry*>& gs) {
  std::size_t n = 0;
  for (const osg::Geometry* g : gs)
    for (unsigned k = 0; k < g->getNumPrimitiveSets(); ++k) n += g->getPrimitiveSet(k)->getNumIndices() / 3;
  return n;
}

// Checks that an LOD's ranges run from the camera out to infinity, each
// starting where the last ends; gives the triangles it draws at the start of
// each range, nearest first.
std::vector<std::size_t> trianglesByRange(const osg::LOD& lod) {
  EXPECT_EQ(lod.getMinRange(0), 0.0f);
  EXPECT_EQ(lod.getMaxRange(lod.getNumChildren() - 1), std::numeric_limits<float>::max());
  std::vector<std::size_t> out;
  for (unsigned k = 0; k < lod.getNumChildren(); ++k) {
    if (k > 0) {
      EXPECT_EQ(lod.getMinRange(k), lod.getMaxRange(k - 1)) << "range " << k;
    }
    std::vector<const osg::Geometry*> drawn;
    drawnAt(&lod, lod.getMinRange(k), drawn);
    out.push_back(triangles(drawn));
  }
  return out;
}

// Whether each count is below the one before.
bool fewerEachTime(const std::vector<std::size_t>& counts) {
  return std::adjacent_find(counts.begin(), counts.end(), std::less_equal<>()) == counts.end();
}

}  // namespace

// Welding draws the very corners it was given, each stored once: a grid of
// n x n cells has (n + 1)^2 distinct corners.
TEST(TerrainLod, WeldingKeepsEveryCornerAndStoresEachOnce) {
  const int n = 40;
  const TriangleBuilder tb = grid(n, 0.1f);
  const osg::ref_ptr<osg::Geometry> g = weldTriangles(tb);
  EXPECT_EQ(vertices(*g).size(), std::size_t((n + 1) * (n + 1)));
  ASSERT_EQ(indices(*g).size(), tb.v->size());
  const auto* uv = static_cast<const osg::Vec2Array*>(g->getTexCoordArray(0));
  ASSERT_NE(uv, nullptr);
  for (std::size_t k = 0; k < tb.v->size(); ++k) {
    const unsigned m = indices(*g)[k];
    EXPECT_EQ(vertices(*g)[m], (*tb.v)[k]) << "corner " << k;
    EXPECT_EQ((*uv)[m], (*tb.uv)[k]) << "corner " << k;
  }
}

// Corners that share a position but not a normal (a crease) stay apart.
TEST(TerrainLod, WeldingKeepsCreasesApart) {
  TriangleBuilder tb;
  const osg::Vec4 white(1, 1, 1, 1);
  tb.triangle(osg::Vec3(0, 0, 0), osg::Vec3(1, 0, 0), osg::Vec3(0, 1, 0), white);  // up
  tb.triangle(osg::Vec3(0, 0, 0), osg::Vec3(0, 1, 0), osg::Vec3(0, 0, 1), white);  // facing -x
  EXPECT_EQ(vertices(*weldTriangles(tb)).size(), 6u);
}

// Clustering a 0.1 m grid at 1 m: on a plane every merged vertex stays on it,
// the square keeps its outline (its area), the triangles drop by about
// (1 / 0.1)^2, and texture coordinates follow the merged positions in world xy.
TEST(TerrainLod, ClusteringKeepsAPlaneAndItsArea) {
  const int n = 100;
  const float h = 0.1f, side = n * h, cell = 1.0f;
  const TriangleBuilder tb = grid(n, h, 0.0f, 0.0f, /*flat=*/true);
  const osg::ref_ptr<osg::Geometry> g = clusterTriangles(tb, cell, kRepeat);
  const auto& v = vertices(*g);
  for (const osg::Vec3& p : v) EXPECT_EQ(p.z(), 0.0f);
  const double area = projectedArea(*g);
  EXPECT_NEAR(area, side * side, 1e-4 * side * side);
  const std::size_t before = tb.v->size() / 3, after = indices(*g).size() / 3;
  EXPECT_LE(after, 4 * before / 100) << before << " -> " << after;  // about 2 (side / cell)^2 left
  const auto* uv = static_cast<const osg::Vec2Array*>(g->getTexCoordArray(0));
  ASSERT_NE(uv, nullptr);
  for (std::size_t m = 0; m < v.size(); ++m) {
    EXPECT_NEAR((*uv)[m].x(), v[m].x() / kRepeat, 1e-6);
    EXPECT_NEAR((*uv)[m].y(), v[m].y() / kRepeat, 1e-6);
  }
}

// On a rolling surface the merged vertices stay within the surface's own
// height range over a cell of it (they are means of corners on it).
TEST(TerrainLod, ClusteredVerticesStayOnTheSurfaceWithinItsVariationOverACell) {
  const float cell = 0.5f;
  const osg::ref_ptr<osg::Geometry> g = clusterTriangles(grid(60, 0.1f), cell, kRepeat);
  // |dz/dx| <= 0.05 * 1.3, |dz/dy| <= 0.05 * 0.7: over a cell's diagonal at most
  const double bound = 0.05 * (1.3 + 0.7) * cell;
  for (const osg::Vec3& p : vertices(*g)) EXPECT_NEAR(p.z(), heightAt(p.x(), p.y()), bound);
}

// Clustering drops triangles that collapse and draws a repeated one once.
TEST(TerrainLod, ClusteringLeavesNoCollapsedOrRepeatedTriangle) {
  const osg::ref_ptr<osg::Geometry> g = clusterTriangles(grid(50, 0.1f), 1.0f, kRepeat);
  const auto& e = indices(*g);
  std::set<std::tuple<unsigned, unsigned, unsigned>> seen;
  for (std::size_t k = 0; k + 2 < e.size(); k += 3) {
    EXPECT_TRUE(e[k] != e[k + 1] && e[k + 1] != e[k + 2] && e[k] != e[k + 2]);
    unsigned a = e[k], b = e[k + 1], c = e[k + 2];
    while (a > b || a > c) std::tie(a, b, c) = std::make_tuple(b, c, a);  // rotate the smallest first
    EXPECT_TRUE(seen.insert({a, b, c}).second);
  }
}

// A sparse tile is one geode; a dense one (a 0.1 m grid 30 m square, 180,000
// triangles) is cut into parts, each switching to coarser stand-ins farther
// out: ranges that join up and reach infinity, fewer triangles at each step.
TEST(TerrainLod, ADenseTileGetsCoarserLevelsFartherOut) {
  osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
  const osg::ref_ptr<osg::Node> sparse = groundTile(grid(20, 1.0f), state.get(), kRepeat);
  EXPECT_NE(sparse->asGeode(), nullptr);

  const osg::ref_ptr<osg::Node> dense = groundTile(grid(300, 0.1f), state.get(), kRepeat);
  osg::Group* parts = dense->asGroup();
  ASSERT_NE(parts, nullptr);
  ASSERT_GT(parts->getNumChildren(), 1u);
  std::size_t total = 0;
  for (unsigned i = 0; i < parts->getNumChildren(); ++i) {
    auto* lod = dynamic_cast<osg::LOD*>(parts->getChild(i));
    ASSERT_NE(lod, nullptr);
    ASSERT_GE(lod->getNumChildren(), 2u) << "part " << i;
    for (unsigned k = 0; k < lod->getNumChildren(); ++k) {
      std::vector<const osg::Geometry*> drawn;
      drawnAt(lod, lod->getMinRange(k), drawn);
      ASSERT_FALSE(drawn.empty());
      for (const osg::Geometry* g : drawn) EXPECT_EQ(g->getStateSet(), state.get());
    }
    // At the start of each range (the nearest range: at the camera, all in full).
    const std::vector<std::size_t> counts = trianglesByRange(*lod);
    EXPECT_TRUE(fewerEachTime(counts)) << "part " << i;
    total += counts[0];
  }
  EXPECT_EQ(total, std::size_t(2 * 300 * 300));  // the parts' full levels together: every triangle once
}

// A part's nearest range is drawn in pieces of a quarter of its side, each
// in full near the camera and, farther than its own distance, as the
// part's first stand-in (the same vertices: one table of means), no later
// than the part itself switches: the full triangles are drawn only next to
// the camera, not over the whole part around it, and the pieces meet the
// part's stand-in and each other.
TEST(TerrainLod, APartIsDrawnInFullOnlyNextToTheCamera) {
  osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
  const osg::ref_ptr<osg::Node> dense = groundTile(grid(125, 0.1f), state.get(), kRepeat);  // one part, 12.5 m
  const osg::Group* parts = dense->asGroup();
  ASSERT_NE(parts, nullptr);
  ASSERT_EQ(parts->getNumChildren(), 1u);
  const auto* lod = dynamic_cast<const osg::LOD*>(parts->getChild(0));
  ASSERT_NE(lod, nullptr);
  ASSERT_GE(lod->getNumChildren(), 2u);
  const float partSwitch = lod->getMaxRange(0);
  const osg::Group* pieces = lod->getChild(0)->asGroup();
  ASSERT_NE(pieces, nullptr);
  ASSERT_EQ(pieces->getNumChildren(), 16u);
  // The part's first stand-in, as drawn just past the nearest range.
  std::vector<const osg::Geometry*> standIn;
  drawnAt(lod, partSwitch, standIn);
  ASSERT_EQ(standIn.size(), 1u);
  std::set<std::tuple<float, float, float>> standInVertices;
  for (const osg::Vec3& p : vertices(*standIn[0])) standInVertices.insert({p.x(), p.y(), p.z()});
  std::size_t full = 0, near = 0;
  for (unsigned i = 0; i < pieces->getNumChildren(); ++i) {
    const auto* piece = dynamic_cast<const osg::LOD*>(pieces->getChild(i));
    ASSERT_NE(piece, nullptr) << "piece " << i;
    ASSERT_EQ(piece->getNumChildren(), 2u);
    EXPECT_EQ(piece->getMinRange(0), 0.0f);
    EXPECT_EQ(piece->getMinRange(1), piece->getMaxRange(0));
    EXPECT_LE(piece->getMaxRange(0), partSwitch) << "piece " << i;
    std::vector<const osg::Geometry*> fine, coarse;
    drawnAt(piece, 0.0f, fine);
    drawnAt(piece, piece->getMaxRange(0), coarse);
    ASSERT_EQ(coarse.size(), 1u);
    full += triangles(fine);
    for (const osg::Vec3& p : vertices(*coarse[0]))
      EXPECT_TRUE(standInVertices.count({p.x(), p.y(), p.z()})) << "piece " << i << ": " << p.x() << ", " << p.y();
    // Drawn from a corner of the part, the pieces nearer than their own distance.
    const osg::Vec3 c = piece->getChild(0)->getBound().center();
    if (c.length() < piece->getMaxRange(0)) near += triangles(fine);
  }
  EXPECT_EQ(full, std::size_t(2 * 125 * 125));  // the pieces in full: every triangle once
  EXPECT_LT(near, full / 2);
}

// The shipped washboard (a generated road mesh: strips across the whole
// road, each cut into two triangles) split into two tiles by the triangles'
// centroids, as the ground splits it: every strip has one triangle in each.
// Both clustered with one table of means, the tiles' stand-ins still cover
// the road together (less a cell at its ends).
TEST(TerrainLod, StandInsOfTwoTilesMeetWhenBothAreClusteredWithOneTable) {
  using namespace bdfcar::terrain;
  const TriangleMesh m = triangulate(loadTerrain(bdfcar::test::asset("terrain/washboard.toml")));
  TriangleBuilder tiles[2];
  for (std::size_t k = 0; k < m.triangles.size(); ++k) {
    const Eigen::Vector3d c = (m.vertices[m.triangles[k][0]] + m.vertices[m.triangles[k][1]] + m.vertices[m.triangles[k][2]]) / 3.0;
    TriangleBuilder& tb = tiles[c.y() < 0.0 ? 0 : 1];
    if (!tb.uv) tb.enableTexcoords();
    for (int i : m.triangles[k]) {
      const Eigen::Vector3d& p = m.vertices[i];
      tb.vertex(osg::Vec3(p.x(), p.y(), p.z()), osg::Vec3(0, 0, 1), osg::Vec4(1, 1, 1, 1),
                osg::Vec2(p.x() / kRepeat, p.y() / kRepeat));
    }
  }
  const LookOutline look({&tiles[0], &tiles[1]});
  const std::vector<std::uint8_t> places[2] = {look.places(tiles[0]), look.places(tiles[1])};
  const std::vector<ClusterMeans> shared = clusterMeans({&tiles[0], &tiles[1]}, {&places[0], &places[1]});
  for (const ClusterMeans& means : shared) {
    // Points over the road (x -50 .. 400, y -10 .. 10) a cell in from its ends.
    std::vector<osg::Vec2> points;
    for (float x = -50.0f + 2 * means.cell + 0.013f; x < 400.0f - 2 * means.cell; x += 0.173f)
      for (float y = -9.93f; y < 10.0f; y += 0.71f) points.emplace_back(x, y);
    osg::ref_ptr<osg::Geometry> together[2];
    for (int i = 0; i < 2; ++i) together[i] = clusterTriangles(tiles[i], means.cell, kRepeat, &places[i], &means);
    EXPECT_EQ(uncovered({together[0].get(), together[1].get()}, points), 0.0) << "cell " << means.cell;
  }
}

// A rolling 0.1 m grid cut in two tiles along x = 10.05 m (through its
// triangles, by their centroids): the corners along the cut, inside the look
// and on its outline where the cut meets it, move in clustering. Both tiles
// clustered with one table still cover the grid along the cut.
TEST(TerrainLod, StandInsOfATileCutThroughItsOutlineMeet) {
  const TriangleBuilder whole = grid(200, 0.1f);
  TriangleBuilder tiles[2];
  for (TriangleBuilder& tb : tiles) tb.enableTexcoords();
  for (std::size_t k = 0; k + 2 < whole.v->size(); k += 3) {
    const float cx = ((*whole.v)[k].x() + (*whole.v)[k + 1].x() + (*whole.v)[k + 2].x()) / 3.0f;
    for (std::size_t j = k; j < k + 3; ++j)
      tiles[cx < 10.05f ? 0 : 1].vertex((*whole.v)[j], (*whole.n)[j], (*whole.c)[j], (*whole.uv)[j]);
  }
  const LookOutline look({&tiles[0], &tiles[1]});
  const std::vector<std::uint8_t> places[2] = {look.places(tiles[0]), look.places(tiles[1])};
  const std::vector<ClusterMeans> shared = clusterMeans({&tiles[0], &tiles[1]}, {&places[0], &places[1]});
  std::vector<osg::Vec2> points;  // along the cut, to a cell from the grid's edges
  for (float y = 0.013f; y < 19.99f; y += 0.0137f)
    for (float x = 9.05f; x < 11.05f; x += 0.25f) points.emplace_back(x, y);
  for (const ClusterMeans& means : shared) {
    osg::ref_ptr<osg::Geometry> together[2];
    for (int i = 0; i < 2; ++i) together[i] = clusterTriangles(tiles[i], means.cell, kRepeat, &places[i], &means);
    EXPECT_EQ(uncovered({together[0].get(), together[1].get()}, points), 0.0) << "cell " << means.cell;
  }
}

// A strip of two looks, asphalt (|y| < 4.1 m) and grass beyond it to 6 m, on
// a 0.1 m grid, each clustered with its own look's outline: at every cell
// size the asphalt's stand-in covers the asphalt side of their line and not
// the grass side, and the grass's the other way round: they meet on the
// line, not on a staircase of columns (the seam the ground's stand-ins drew
// before), and leave no slit between them.
TEST(TerrainLod, StandInsOfTwoLooksMeetOnTheirLine) {
  TriangleBuilder asphalt = grid(0, 0.1f), grass = grid(0, 0.1f);
  const int nx = 200, ny = 120;  // 20 m x 12 m from (0, -6)
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      TriangleBuilder& tb = std::abs(-6.0f + (j + 0.5f) * 0.1f) < 4.1f ? asphalt : grass;
      auto corner = [&](int ci, int cj) {  // from the indices: a corner is the same in every cell
        const float x = ci * 0.1f, y = -6.0f + cj * 0.1f;
        tb.vertex(osg::Vec3(x, y, 0), osg::Vec3(0, 0, 1), osg::Vec4(1, 1, 1, 1), osg::Vec2(x / kRepeat, y / kRepeat));
      };
      corner(i, j), corner(i + 1, j), corner(i + 1, j + 1);
      corner(i, j), corner(i + 1, j + 1), corner(i, j + 1);
    }
  std::vector<osg::Vec2> inside, outside;  // 2 cm either side of the line y = 4.1 (and -4.1)
  for (float x = 4.013f; x < 16.0f; x += 0.097f)
    for (float side : {1.0f, -1.0f}) {
      inside.emplace_back(x, side * 4.08f);
      outside.emplace_back(x, side * 4.12f);
    }
  for (float cell : {0.25f, 1.0f, 4.0f}) {
    const osg::ref_ptr<osg::Geometry> a = clusterTriangles(asphalt, cell, kRepeat);
    const osg::ref_ptr<osg::Geometry> g = clusterTriangles(grass, cell, kRepeat);
    EXPECT_EQ(uncovered({a.get()}, inside), 0.0) << "cell " << cell;
    EXPECT_EQ(uncovered({a.get()}, outside), 1.0) << "cell " << cell;
    EXPECT_EQ(uncovered({g.get()}, outside), 0.0) << "cell " << cell;
    EXPECT_EQ(uncovered({g.get()}, inside), 1.0) << "cell " << cell;
  }
}

// What a stand-in takes away decides where it is used: a level dense tile
// (no relief) is drawn from its coarsest stand-in at once, every part's first
// level far lighter than its triangles; relief keeps the full triangles
// nearest, and the same relief ten times lower switches to each coarser
// level no later, and sooner for the finest.
TEST(TerrainLod, TheReliefAStandInTakesAwayDecidesWhereItIsUsed) {
  osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
  std::vector<osg::ref_ptr<osg::Node>> tiles;  // hold the parts' LODs for the test's length
  auto firstLevels = [&](const TriangleBuilder& tb) {
    std::vector<const osg::LOD*> lods;
    const osg::Node* node = tiles.emplace_back(groundTile(tb, state.get(), kRepeat)).get();
    for (unsigned i = 0; i < node->asGroup()->getNumChildren(); ++i)
      lods.push_back(dynamic_cast<const osg::LOD*>(node->asGroup()->getChild(i)));
    return lods;
  };
  const int n = 200;
  for (const osg::LOD* lod : firstLevels(grid(n, 0.1f, 0.0f, 0.0f, /*flat=*/true))) {
    ASSERT_NE(lod, nullptr);
    EXPECT_EQ(lod->getMinRange(0), 0.0f);
    std::vector<const osg::Geometry*> first;
    drawnAt(lod, 0.0f, first);
    EXPECT_LT(triangles(first), std::size_t(2 * 125 * 125 / 20));  // a part is 12.5 m square at most
  }
  TriangleBuilder low = grid(n, 0.1f);
  for (osg::Vec3& p : *low.v) p.z() *= 0.1f;
  const std::vector<const osg::LOD*> high = firstLevels(grid(n, 0.1f)), lower = firstLevels(low);
  ASSERT_EQ(high.size(), lower.size());
  for (std::size_t i = 0; i < high.size(); ++i) {
    ASSERT_GE(high[i]->getNumChildren(), 2u);
    ASSERT_EQ(high[i]->getNumChildren(), lower[i]->getNumChildren()) << "part " << i;
    EXPECT_LT(lower[i]->getMaxRange(0), high[i]->getMaxRange(0)) << "part " << i;
    for (unsigned k = 0; k + 1 < high[i]->getNumChildren(); ++k)
      EXPECT_LE(lower[i]->getMaxRange(k), high[i]->getMaxRange(k)) << "part " << i << " level " << k;
  }
}

// A tile too sparse for parts of its own, laid over another layer (a
// circuit's curbs), is drawn whole near the camera and thinned far away:
// ranges that join up and reach infinity, fewer triangles at each step; a
// tile of a few triangles stays one geode.
TEST(TerrainLod, ASparseTileIsThinnedOnlyFarAway) {
  osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
  const osg::ref_ptr<osg::Node> few = thinnedWithDistance(grid(8, 1.0f), state.get(), kRepeat);
  EXPECT_NE(few->asGeode(), nullptr);

  const osg::ref_ptr<osg::Node> tile = thinnedWithDistance(grid(60, 0.5f), state.get(), kRepeat);
  const auto* lod = dynamic_cast<const osg::LOD*>(tile.get());
  ASSERT_NE(lod, nullptr);
  ASSERT_GE(lod->getNumChildren(), 2u);
  for (unsigned k = 0; k < lod->getNumChildren(); ++k)
    EXPECT_EQ(lod->getChild(k)->asGeode()->getDrawable(0)->getStateSet(), state.get());
  const std::vector<std::size_t> counts = trianglesByRange(*lod);
  EXPECT_EQ(counts[0], std::size_t(2 * 60 * 60));  // at the camera: every triangle
  EXPECT_TRUE(fewerEachTime(counts));
}

namespace {

// z of a rough road: ripples along it, a gentle camber across.
double roughRoad(double x, double y) { return 0.03 * std::sin(2.1 * x) + 0.015 * std::sin(7.3 * x + 1.0) + 0.01 * y; }

}  // namespace

// Road paint far away follows the road's relief more loosely, in fewer
// triangles, but never sinks into it: every level of every piece, sampled
// along its triangles' edges, stays above the surface by at least the
// finest level's margin (its 2 cm lift less its 4 mm tolerance), and a
// coarser level strays from that lift by under a pixel where it takes over.
TEST(RoadPaint, FarPaintFollowsARoughRoadMoreLooselyAndNeverSinksIntoIt) {
  using namespace bdfcar::terrain;
  TerrainData road;
  road.kind = TerrainKind::Heightfield;
  road.dx = road.dy = 0.05;
  road.x0 = -1.0;
  road.y0 = -5.0;
  road.cols = 2441;  // x to 121 m
  road.rows = 201;   // y to 5 m
  for (int r = 0; r < road.rows; ++r)
    for (int c = 0; c < road.cols; ++c) road.heights.push_back(roughRoad(road.x0 + c * road.dx, road.y0 + r * road.dy));
  road.road.present = true;
  road.road.startX = 0.0;
  road.road.endX = 120.0;
  const TriangleMesh mesh = bdfcar::render::terrainSurface(road);
  const SurfaceSampler ground(mesh);
  const osg::ref_ptr<osg::Node> paint = makeRoadNode(road, ground);
  const osg::Group* pieces = paint->asGroup();
  ASSERT_NE(pieces, nullptr);
  ASSERT_GE(pieces->getNumChildren(), 3u);  // 120 m in 50 m pieces
  constexpr double kLift = 0.02, kFinest = 0.004;
  for (unsigned i = 0; i < pieces->getNumChildren(); ++i) {
    const auto* lod = dynamic_cast<const osg::LOD*>(pieces->getChild(i));
    ASSERT_NE(lod, nullptr) << "piece " << i;
    ASSERT_GE(lod->getNumChildren(), 2u) << "piece " << i;
    EXPECT_TRUE(fewerEachTime(trianglesByRange(*lod))) << "piece " << i;
    for (unsigned k = 0; k < lod->getNumChildren(); ++k) {
      const osg::Geometry* g = lod->getChild(k)->asGeode()->getDrawable(0)->asGeometry();
      const auto& v = vertices(*g);
      double lowest = 1.0, stray = 0.0;
      for (std::size_t t = 0; t + 2 < v.size(); t += 3)
        for (int e = 0; e < 3; ++e)
          for (int s = 0; s < 8; ++s) {
            const osg::Vec3 p = v[t + e] + (v[t + (e + 1) % 3] - v[t + e]) * (s / 8.0f);
            const double above = p.z() - *ground.height(p.x(), p.y());
            lowest = std::min(lowest, above);
            stray = std::max(stray, std::abs(above - kLift));
          }
      EXPECT_GE(lowest, kLift - kFinest - 1e-4) << "piece " << i << " level " << k;
      if (k > 0) {
        EXPECT_LE(underAPixelFrom(float(stray)), lod->getMinRange(k) - g->getBound().radius())
            << "piece " << i << " level " << k;
      }
    }
  }
}

// Far cones are drawn with fewer sides, each level from where it falls short
// of the round cone (0.5 m tall on a 3 cm base, radius 0.15 m at its foot,
// 0.025 m at its top) by under a pixel: sampled along its body's triangle
// edges, no point lies outside the round cone, and the deepest shortfall is
// under a pixel at the level's nearest distance; fewer triangles each level.
TEST(ConeLod, FarConesHaveFewerSidesAndKeepTheirOutlineToAPixel) {
  bdfcar::terrain::TerrainData plane;  // a level plane at z = 0
  const bdfcar::terrain::TriangleMesh mesh = bdfcar::render::terrainSurface(plane);
  const osg::ref_ptr<osg::Group> cones = makeConesNode({Eigen::Vector3d(0, 0, 0)}, SurfaceSampler(mesh));
  ASSERT_EQ(cones->getNumChildren(), 1u);
  const auto* lod = dynamic_cast<const osg::LOD*>(cones->getChild(0)->asGroup()->getChild(0));
  ASSERT_NE(lod, nullptr);
  ASSERT_GE(lod->getNumChildren(), 2u);
  constexpr double kFoot = 0.03, kTop = 0.5, kR0 = 0.15, kR1 = 0.025;
  EXPECT_TRUE(fewerEachTime(trianglesByRange(*lod)));
  for (unsigned k = 0; k < lod->getNumChildren(); ++k) {
    const osg::Geometry* g = lod->getChild(k)->asGeode()->getDrawable(0)->asGeometry();
    const auto& v = vertices(*g);
    double shortfall = 0.0;
    int body = 0;
    for (std::size_t t = 0; t + 2 < v.size(); t += 3)
      for (int e = 0; e < 3; ++e)
        for (int s = 0; s < 8; ++s) {
          const osg::Vec3 p = v[t + e] + (v[t + (e + 1) % 3] - v[t + e]) * (s / 8.0f);
          if (p.z() <= kFoot + 1e-4) continue;  // the base plate
          ++body;
          const double round = kR0 + (kR1 - kR0) * (p.z() - kFoot) / (kTop - kFoot);
          const double off = round - std::hypot(p.x(), p.y());
          EXPECT_GE(off, -1e-5) << "level " << k << " outside the round cone at z " << p.z();
          shortfall = std::max(shortfall, off);
        }
    ASSERT_GT(body, 0);
    if (k > 0) {  // the nearest level is the cone as it always was
      EXPECT_LE(underAPixelFrom(float(shortfall)), lod->getMinRange(k) - g->getBound().radius()) << "level " << k;
    }
  }
}
