// Tracks and grounds (the proving ground's terrain): a generated track's
// centre line against the circle and arc lengths it is made of; rays on a
// track's asphalt, its curbs and the grass beside it against the heights and
// frictions written in the file; a piece turned on a ground against the same
// piece unturned (a rotation of the rays); a pothole piece below the ground's
// plane; loader errors naming file, line and key; the shipped proving
// ground's circuit length against its segment list summed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "terrain/bullet/bullet_terrain.h"
#include "terrain/terrain_file.h"
#include "terrain/terrain_mesh.h"
#include "terrain/track.h"
#include "test_files.h"

using namespace bdfcar::terrain;
using bdfcar::test::asset;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = bdfcar::test::tempFile("proving_ground", name);
  std::ofstream(path) << text;
  return path;
}

// The surface under (x, y): a vertical ray from 10 m up.
Hit below(const Terrain& t, double x, double y) { return t.castRay({x, y, 10.0}, {0, 0, -1}, 20.0); }

double polylineLength(const std::vector<Vector2d>& p, bool closed) {
  double l = 0;
  for (std::size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
  return closed ? l + (p.front() - p.back()).norm() : l;
}

// A ring track: one 360 degree left arc of radius 30 m, 8 m wide, curbs both sides.
const char* kRing = R"(name = "ring"
kind = "track"
friction = 0.95
[track]
width = 8.0
curb_width = 1.0
curb_height = 0.05
closed = true
cell = 1.0
[[track.segments]]
radius = 30.0
angle_deg = 360.0
curbs = "both"
)";

}  // namespace

// Every centre-line point of an arc lies on its circle, and the chords add
// up to the arc length within the chord error (c^2 / (24 R^2) relative).
TEST(Track, AnArcsCentreLineLiesOnItsCircle) {
  Track t;
  t.segments = {{100.0, 0, 0, TrackSegment::Curbs::None}, {0, 25.0, 120 * kDeg, TrackSegment::Curbs::None},
                {0, 40.0, -60 * kDeg, TrackSegment::Curbs::None}};
  t.cell = 2.0;
  const std::vector<CentreLinePoint> line = sampleCentreLine(t);
  // First arc: starts at (100, 0) heading +x, turning left: centre (100, 25).
  const Vector2d c1(100, 25);
  // Second: starts where the first ends, heading 120 deg, turning right: its centre is to the right.
  const Vector2d end1 = c1 + 25.0 * Vector2d(std::sin(120 * kDeg), -std::cos(120 * kDeg));
  const Vector2d c2 = end1 + 40.0 * Vector2d(std::sin(120 * kDeg), -std::cos(120 * kDeg));
  double chords = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    chords += (line[i].p - line[i - 1].p).norm();
    if (line[i].segment == 1) {
      EXPECT_NEAR((line[i].p - c1).norm(), 25.0, 1e-9);
    }
    if (line[i].segment == 2) {
      EXPECT_NEAR((line[i].p - c2).norm(), 40.0, 1e-9);
    }
  }
  const double arcs = 100.0 + 25.0 * 120 * kDeg + 40.0 * 60 * kDeg;
  EXPECT_NEAR(line.back().s, arcs, 1e-9);
  EXPECT_NEAR(chords, arcs, arcs * 4.0 / (24 * 25.0 * 25.0));
  EXPECT_LT(chords, arcs);
  EXPECT_NEAR(line.back().heading, 60 * kDeg, 1e-12);
}

// The ring as the tyres see it: asphalt at z = 0 on the centre line, the
// curb's flat top (its full height half way round, away from the taper at
// the ends of the arc) just beyond each edge, nothing beyond the curbs.
TEST(Track, RaysReadTheRibbonItsCurbsAndNothingBeyond) {
  const TerrainData d = loadTerrain(writeTemp("ring.toml", kRing));
  ASSERT_EQ(d.kind, TerrainKind::Mesh);
  ASSERT_EQ(d.triangleMaterials.size(), d.triangles.size());
  EXPECT_TRUE(d.centreLineClosed);
  EXPECT_NEAR(polylineLength(d.centreLine, true), 2 * std::numbers::pi * 30.0, 2 * std::numbers::pi * 30.0 * 1.0 / (24 * 900.0));
  const std::unique_ptr<Terrain> t = makeTerrain(d);
  // Half way round: the centre line at (0, 60), heading -x; the circle's centre (0, 30).
  const Hit centre = below(*t, 0.0, 60.0);
  ASSERT_TRUE(centre.hit);
  EXPECT_NEAR(centre.point.z(), 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(centre.friction, 0.95);
  for (double r : {30.0 + 4.5, 30.0 - 4.5}) {  // mid-curb outside and inside: radius 30 +- (4 + 0.5)
    const Hit curb = below(*t, 0.0, 30.0 + r);
    ASSERT_TRUE(curb.hit) << r;
    EXPECT_NEAR(curb.point.z(), 0.05, 2e-4) << r;  // the chord's sag across the 0.7 m top: < 1e-4 m
  }
  EXPECT_FALSE(below(*t, 0.0, 30.0 + 6.0).hit);  // beyond the outer curb
  EXPECT_FALSE(below(*t, 0.0, 30.0).hit);        // the infield
}

// A ground: the ring turned by 90 degrees and moved, on grass. Each ray on
// the ground reads what the same ray, turned back, reads on the ring alone.
TEST(Ground, APieceTurnedOnTheGroundIsTheSamePieceUnderTurnedRays) {
  writeTemp("ring.toml", kRing);
  const std::string ground = writeTemp("ground.toml", R"(name = "test ground"
kind = "ground"
friction = 0.4
[[pieces]]
terrain = "bdfcar_proving_ground_ring.toml"
at = [100.0, -20.0, 0.0]
heading_deg = 90.0
)");
  const TerrainData g = loadTerrain(ground);
  ASSERT_EQ(g.pieces.size(), 1u);
  EXPECT_EQ(g.pieces[0].name, "ring");
  const std::unique_ptr<Terrain> world = makeTerrain(g);
  const std::unique_ptr<Terrain> ring = makeTerrain(g.pieces[0].terrain);
  int onRing = 0;
  for (double a = 0; a < 2 * std::numbers::pi; a += 0.1)
    for (double r : {20.0, 26.0, 30.0, 34.5, 40.0}) {
      const Vector3d local(r * std::cos(a), 30.0 + r * std::sin(a), 10.0);
      // Turned +90 deg: (x, y) -> (-y, x), then moved by (100, -20).
      const Vector3d from(100.0 - local.y(), -20.0 + local.x(), 10.0);
      const Hit w = world->castRay(from, {-0.3, 0.0, -1.0}, 30.0);
      const Hit l = ring->castRay(local, {0.0, 0.3, -1.0}, 30.0);  // the same ray direction turned back
      ASSERT_TRUE(w.hit);
      if (!l.hit) {  // off the ring: the ground's plane, grass
        EXPECT_NEAR(w.point.z(), 0.0, 1e-12);
        EXPECT_DOUBLE_EQ(w.friction, 0.4);
        continue;
      }
      ++onRing;
      EXPECT_NEAR(w.distance, l.distance, 1e-6);
      EXPECT_DOUBLE_EQ(w.friction, 0.95);
      EXPECT_NEAR(w.normal.x(), -l.normal.y(), 1e-9);
      EXPECT_NEAR(w.normal.y(), l.normal.x(), 1e-9);
      EXPECT_NEAR(w.normal.z(), l.normal.z(), 1e-9);
    }
  EXPECT_GT(onRing, 60);
  // Drawn: the plane's two triangles plus the ring's, materials along.
  const TriangleMesh m = triangulate(g);
  EXPECT_EQ(m.materials.size(), m.triangles.size());
}

// Over a piece's footprint the piece is the surface, so a pothole in it is
// felt though the ground's plane passes over it.
TEST(Ground, APotholeInAPieceIsBelowTheGroundsPlane) {
  const std::string ground = writeTemp("pothole_ground.toml", "kind = \"ground\"\nfriction = 0.4\n"
                                                              "[[pieces]]\nterrain = \"" + asset("terrain/pothole.toml") +
                                                              "\"\nat = [0.0, 0.0]\n");
  const TerrainData g = loadTerrain(ground);
  const TerrainData alone = loadTerrain(asset("terrain/pothole.toml"));
  const std::unique_ptr<Terrain> world = makeTerrain(g), piece = makeTerrain(alone);
  double deepest = 0;
  for (double x = 25; x < 35; x += 0.05) {
    const Hit w = below(*world, x, -2.55), p = below(*piece, x, -2.55);
    ASSERT_TRUE(w.hit && p.hit);
    EXPECT_DOUBLE_EQ(w.point.z(), p.point.z()) << x;
    deepest = std::min(deepest, w.point.z());
  }
  EXPECT_LT(deepest, -0.02);  // the pothole was crossed
}

// A circuit that does not close, a segment that is neither straight nor
// arc, a piece that is a plane: each refused with the file, line and key.
TEST(Ground, BadTracksAndPiecesAreRefusedNamingFileLineAndKey) {
  auto errorOf = [](const std::string& path) {
    try {
      loadTerrain(path);
    } catch (const TerrainFileError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string open = writeTemp("open_circuit.toml",
                                     "kind = \"track\"\nfriction = 1.0\n[track]\nwidth = 10.0\nclosed = true\n"
                                     "[[track.segments]]\nstraight = 100.0\n[[track.segments]]\nradius = 20.0\nangle_deg = 180.0\n");
  const std::string e1 = errorOf(open);
  EXPECT_NE(e1.find(open + ":5:"), std::string::npos) << e1;
  EXPECT_NE(e1.find("'track.closed'"), std::string::npos) << e1;
  // 100 m, then a half circle of radius 20: it ends at (100, 40) heading back, hypot(100, 40) = 107.703 m away.
  EXPECT_NE(e1.find("ends 107.703 m away, 180.000 deg off"), std::string::npos) << e1;

  const std::string both = writeTemp("both.toml", "kind = \"track\"\nfriction = 1.0\n[track]\nwidth = 10.0\n"
                                                  "[[track.segments]]\nstraight = 100.0\nradius = 20.0\n");
  const std::string e2 = errorOf(both);
  EXPECT_NE(e2.find(both + ":6:"), std::string::npos) << e2;
  EXPECT_NE(e2.find("not both"), std::string::npos) << e2;

  const std::string plane = writeTemp("plane_piece.toml", "kind = \"ground\"\nfriction = 0.5\n[[pieces]]\nterrain = \"" +
                                                              asset("terrain/flat.toml") + "\"\nat = [0.0, 0.0]\n");
  const std::string e3 = errorOf(plane);
  EXPECT_NE(e3.find("flat.toml:"), std::string::npos) << e3;
  EXPECT_NE(e3.find("'kind'"), std::string::npos) << e3;
}

// The shipped proving ground: the circuit's centre line is as long as its
// segments, summed here from the file's numbers; it closes; its start line
// is asphalt and the grass beside it has the ground's friction.
TEST(Ground, TheProvingGroundsCircuitIsAsLongAsItsSegments) {
  const TerrainData g = loadTerrain(asset("terrain/proving_ground.toml"));
  WorldCentreLine line;
  ASSERT_TRUE(findCentreLine(g, "circuit", line));
  EXPECT_TRUE(line.closed);
  const double straights = 800 + 150 + 113.223304703363 + 323.209518073863 + 250 + 320;
  const double arcs = kDeg * (90 * 70 + 45 * 150 + 45 * 100 + 90 * 80 + 40 * 60 + 80 * 50 + 40 * 60 + 90 * 60 +
                              30 * 120 + 30 * 120 + 90 * 90);
  // Chords of at most 2 m on radii of at least 50 m: shorter by < 2^2 / (24 * 50^2).
  EXPECT_NEAR(polylineLength(line.points, true), straights + arcs, (straights + arcs) * 4.0 / (24 * 2500.0));
  EXPECT_NEAR(straights + arcs, 2903.3, 0.05);
  const std::unique_ptr<Terrain> t = makeTerrain(g);
  EXPECT_DOUBLE_EQ(below(*t, 5.0, 0.0).friction, 1.0);    // start line: asphalt
  EXPECT_DOUBLE_EQ(below(*t, 5.0, -20.0).friction, 0.45);  // grass
  const Hit gravel = below(*t, 910.0, 60.0);
  EXPECT_DOUBLE_EQ(gravel.friction, 0.55);
  // The 10 % slope at (610, -60): 2 m up its face (20 m from its foot at x = 620) the surface is 2 m high.
  const Hit slope = below(*t, 640.0, -60.0);
  EXPECT_NEAR(slope.point.z(), 2.0, 1e-4);
  EXPECT_NEAR(slope.normal.dot(Vector3d(-0.1, 0, 1).normalized()), 1.0, 1e-6);
}

namespace {

// Heights of the drawn triangles above (x, y), brute force.
std::vector<double> drawnHeights(const TriangleMesh& m, double x, double y) {
  std::vector<double> out;
  for (const auto& t : m.triangles) {
    const Vector3d &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (std::abs(det) < 1e-12) continue;
    const double u = ((x - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (y - a.y())) / det;
    const double v = ((b.x() - a.x()) * (y - a.y()) - (x - a.x()) * (b.y() - a.y())) / det;
    if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) continue;
    out.push_back(a.z() + u * (b.z() - a.z()) + v * (c.z() - a.z()));
  }
  return out;
}

}  // namespace

// What is drawn of a ground is what the tyres touch: over the proving
// ground's rough road and washboard (pieces whose relief dips below the
// ground's plane) and beside them, the highest drawn surface is the one the
// rays find, within a millimetre, and nothing drawn lies above it. Drawing
// the plane across the pieces, as it once was, puts grass over every dip.
TEST(Ground, TheDrawnSurfaceIsTheQueriedOneWhereAPieceDipsBelowThePlane) {
  const TerrainData g = loadTerrain(asset("terrain/proving_ground.toml"));
  const std::unique_ptr<Terrain> t = makeTerrain(g);
  const TriangleMesh m = triangulate(g);
  ASSERT_EQ(m.materials.size(), m.triangles.size());
  int below0 = 0, checked = 0;
  // Across the rough road (y -166 .. -154) and the washboard (y -210 .. -190), and the grass between.
  for (double x = 31.37; x < 190; x += 7.31)
    for (double y = -212.0; y <= -152.0; y += 0.83) {
      const Hit h = below(*t, x, y);
      ASSERT_TRUE(h.hit);
      const std::vector<double> drawn = drawnHeights(m, x, y);
      ASSERT_FALSE(drawn.empty()) << x << ", " << y;
      EXPECT_NEAR(*std::max_element(drawn.begin(), drawn.end()), h.point.z(), 1e-3) << x << ", " << y;
      below0 += h.point.z() < -1e-3;
      ++checked;
    }
  EXPECT_GT(below0, 50) << "of " << checked;  // the relief does dip below the plane (127 points of 1600)
}

// The road's lanes and shoulders on relief are drawn as asphalt (the
// surface's own triangles, no ribbon over them); the rough road's grass
// verges stay grass.
TEST(Ground, ARoadOnReliefIsDrawnAsAsphaltOverItsLanes) {
  const TerrainData rough = loadTerrain(asset("terrain/rough.toml"));
  ASSERT_TRUE(rough.road.present);
  const TriangleMesh m = triangulate(rough);
  const double half = rough.road.asphaltHalfWidth();
  int lanes = 0, verges = 0;
  for (std::size_t k = 0; k < m.triangles.size(); k += 101) {
    const auto& t = m.triangles[k];
    const Vector3d centre = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
    const bool onRoad = std::abs(centre.y() - rough.road.centreY) <= half;
    EXPECT_EQ(m.materials[k], onRoad ? Material::Asphalt : rough.material) << centre.transpose();
    (onRoad ? lanes : verges) += 1;
  }
  EXPECT_GT(lanes, 0);
  EXPECT_GT(verges, 0);
}
