// Terrain: the analytic plane against hand-solved rays; Bullet meshes and
// heightfields against the plane, analytic ramp and bump profiles and each
// other; the drawn triangles against the queried surface; loader errors that
// name file, line and key; the shipped assets' documented layout;
// determinism, concurrent reads and no heap allocation per ray.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "terrain/bullet/bullet_terrain.h"
#include "terrain/bullet/bullet_shapes.h"
#include "terrain/road_surface.h"
#include "terrain/terrain.h"
#include "terrain/terrain_file.h"
#include "terrain/terrain_mesh.h"

using namespace bdfcar::terrain;
using Eigen::Vector3d;

// ---------------------------------------------------------------------------
// Heap allocation counter: this test binary replaces malloc and friends with
// counting wrappers around glibc's own allocator, so allocations made inside
// the Bullet shared libraries are seen too. Compiled only with
// BDFCAR_ALLOCATION_COUNTERS (tests/terrain.cmake): AddressSanitizer must own
// malloc, so sanitizer builds leave it out and skip the one test that counts.
#if BDFCAR_ALLOCATION_COUNTERS
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {
std::atomic<long> gAllocations{0};
}  // namespace

extern "C" {
void* malloc(std::size_t n) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(std::size_t count, std::size_t n) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, n);
}
void* realloc(void* p, std::size_t n) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
void* memalign(std::size_t alignment, std::size_t n) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) { return memalign(alignment, n); }
int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = memalign(alignment, n);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
void free(void* p) { __libc_free(p); }
}
#endif  // BDFCAR_ALLOCATION_COUNTERS

namespace {

constexpr double kTol = 1e-9;  // m, and for unit normals

// ---------------------------------------------------------------------------
// Fixtures built in code.

// A flat square [-h, h]^2 at height z as two triangles.
TerrainData flatSquareMesh(double h, double z) {
  TerrainData d;
  d.kind = TerrainKind::Mesh;
  d.vertices = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
  d.triangles = {{0, 1, 2}, {0, 2, 3}};
  return d;
}

// A flat heightfield of cols x rows points from (x0, y0), spacing d, at height z.
TerrainData flatHeightfield(int cols, int rows, double x0, double y0, double d, double z) {
  TerrainData t;
  t.kind = TerrainKind::Heightfield;
  t.cols = cols;
  t.rows = rows;
  t.x0 = x0;
  t.y0 = y0;
  t.dx = t.dy = d;
  t.heights.assign(static_cast<std::size_t>(rows) * cols, z);
  return t;
}

// A road built as a mesh or as a heightfield.
TerrainData built(const RoadSurface& road, bool asMesh) {
  TerrainData d;
  d.friction = 0.9;
  asMesh ? buildRoadMesh(road, d) : buildRoadHeightfield(road, d);
  return d;
}

// Height of a terrain under (x, y) by a vertical ray from 10 m above.
double heightUnder(const Terrain& t, double x, double y) {
  const Hit h = t.castRay({x, y, 10.0}, {0, 0, -1}, 20.0);
  EXPECT_TRUE(h.hit) << "no ground under (" << x << ", " << y << ")";
  return h.point.z();
}

void expectNear(const Vector3d& a, const Vector3d& b, double tol, const std::string& what) {
  EXPECT_LT((a - b).norm(), tol) << what << ": (" << a.transpose() << ") vs (" << b.transpose() << ")";
}

// Point, normal and distance of two hits agree.
void expectSameHit(const Hit& a, const Hit& b, const std::string& what) {
  ASSERT_EQ(a.hit, b.hit) << what;
  if (!a.hit) return;
  expectNear(a.point, b.point, kTol, what + " point");
  expectNear(a.normal, b.normal, kTol, what + " normal");
  EXPECT_NEAR(a.distance, b.distance, kTol) << what;
}

bool sameBits(const Hit& a, const Hit& b) {
  return a.hit == b.hit && std::memcmp(a.point.data(), b.point.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(a.normal.data(), b.normal.data(), sizeof(double) * 3) == 0 &&
         std::memcmp(&a.distance, &b.distance, sizeof(double)) == 0 && a.friction == b.friction;
}

// A rough road with one patch (waves drawn from the seed).
RoadSurface roughRoad(std::uint64_t seed, double cell) {
  RoadSurface road{.xMin = 0, .xMax = 40, .yMin = -5, .yMax = 5, .cell = cell};
  RoughPatch p{.seed = seed, .xMin = 2, .xMax = 38, .rmsHeight = 0.02, .wavelengthMax = 8.0, .waveCount = 48};
  makeRoughWaves(p);
  road.rough.push_back(p);
  return road;
}

// Random rays starting above [-r, r]^2 at height to 2 height, pointing
// downwards, each horizontal component up to `slant` times at least half a vertical one.
struct Ray {
  Vector3d from, direction;
};
std::vector<Ray> downwardRays(int n, double r, double height, unsigned seed, double slant = 0.8) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i)
    rays.push_back({{r * u(rng), r * u(rng), height * (1.5 + 0.5 * u(rng))},
                    {slant * u(rng), slant * u(rng), -0.5 - 0.5 * std::abs(u(rng))}});
  return rays;
}

std::string assetPath(const std::string& name) { return std::string(BDFCAR_ASSETS_DIR) + "/terrain/" + name; }

// A scratch directory for hand-written files, removed when the program ends.
std::filesystem::path scratchDir() {
  struct Scratch {
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("bdfcar_terrain_test_" + std::to_string(::getpid()));
    Scratch() { std::filesystem::create_directories(dir); }
    ~Scratch() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  };
  static const Scratch scratch;
  return scratch.dir;
}

std::string writeFile(const std::string& name, const std::string& content) {
  const std::filesystem::path p = scratchDir() / name;
  std::ofstream(p) << content;
  return p.string();
}

// The message loadTerrain throws for a file with this content ("" if it loads).
std::string loadError(const std::string& name, const std::string& content) {
  const std::string path = writeFile(name, content);
  try {
    loadTerrain(path);
  } catch (const TerrainFileError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

// ---------------------------------------------------------------------------
// Analytic plane.

TEST(PlaneTerrain, HandSolvedTiltedPlaneIntersection) {
  // Plane through (1, 2, 3) with normal (0, 0.6, 0.8); ray from (0, 0, 10)
  // along (0, 0, -2): n.(p - from) = 0.6 * 2 + 0.8 * (3 - 10) = -4.4, n.d = -0.8,
  // so s = 5.5 m and the hit is (0, 0, 4.5).
  const PlaneTerrain plane({1, 2, 3}, {0, 0.6, 0.8}, 0.7);
  const Hit h = plane.castRay({0, 0, 10}, {0, 0, -2}, 100.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 5.5, 1e-12);
  expectNear(h.point, {0, 0, 4.5}, 1e-12, "point");
  expectNear(h.normal, {0, 0.6, 0.8}, 1e-12, "normal");
  EXPECT_EQ(h.friction, 0.7);
  // An oblique ray: from (0, 0, 1) along (1, 0, -1) to the plane z = 0 hits (1, 0, 0) at sqrt(2).
  const Hit o = PlaneTerrain().castRay({0, 0, 1}, {1, 0, -1}, 10.0);
  ASSERT_TRUE(o.hit);
  EXPECT_NEAR(o.distance, std::sqrt(2.0), 1e-12);
  expectNear(o.point, {1, 0, 0}, 1e-12, "oblique point");
}

TEST(PlaneTerrain, RandomRaysLandOnThePlaneAndOnTheRay) {
  const Vector3d p(3, -2, 0.4), n = Vector3d(0.1, -0.2, 1).normalized();
  const PlaneTerrain plane(p, n);
  // Origins at z >= 15 m, above the plane (at most ~7 m high) everywhere over [-20, 20]^2.
  for (const Ray& r : downwardRays(200, 20, 15, 1)) {
    const Hit h = plane.castRay(r.from, r.direction, 100.0);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(n.dot(h.point - p), 0.0, 1e-12);                                         // on the plane
    expectNear(h.point, r.from + h.distance * r.direction.normalized(), 1e-12, "on ray");  // on the ray
  }
}

TEST(PlaneTerrain, RaysThatMissReportNoHit) {
  const PlaneTerrain plane;
  EXPECT_FALSE(plane.castRay({0, 0, 1}, {0, 0, 1}, 10).hit);          // pointing away
  EXPECT_FALSE(plane.castRay({0, 0, 1}, {0, 0, -1}, 0.5).hit);        // too short
  EXPECT_FALSE(plane.castRay({0, 0, 1}, {1, 0, 0}, 10).hit);          // parallel
  EXPECT_FALSE(plane.castRay({0, 0, 1}, {0, 0, 0}, 10).hit);          // no direction
  EXPECT_FALSE(plane.castRay({NAN, 0, 1}, {0, 0, -1}, 10).hit);       // not a number
}

// ---------------------------------------------------------------------------
// Bullet terrains against the analytic plane.

TEST(BulletTerrain, FlatMeshAndHeightfieldMatchThePlane) {
  const double z = 0.3;
  const auto plane = makeTerrain([&] {
    TerrainData d;
    d.planePoint = {0, 0, z};
    return d;
  }());
  const auto mesh = makeTerrain(flatSquareMesh(50, z));
  const auto field = makeTerrain(flatHeightfield(101, 81, -50, -40, 1.0, z));
  for (const Ray& r : downwardRays(500, 20, 3, 2)) {
    const Hit expected = plane->castRay(r.from, r.direction, 50);
    ASSERT_TRUE(expected.hit);
    expectSameHit(mesh->castRay(r.from, r.direction, 50), expected, "mesh");
    expectSameHit(field->castRay(r.from, r.direction, 50), expected, "heightfield");
  }
  // From below, the ground still faces up, as the plane's normal does.
  const Hit below = mesh->castRay({1, 2, -1}, {0, 0, 1}, 5);
  expectSameHit(below, plane->castRay({1, 2, -1}, {0, 0, 1}, 5), "mesh from below");
}

TEST(BulletTerrain, TiltedMeshMatchesTiltedPlane) {
  // A square tilted by 20 degrees about x: normal (0, -sin b, cos b).
  const double b = 20.0 * std::numbers::pi / 180.0;
  const Vector3d n(0, -std::sin(b), std::cos(b)), along(0, std::cos(b), std::sin(b));
  TerrainData d;
  d.kind = TerrainKind::Mesh;
  const double h = 100;
  // Wound clockwise seen from above: the reported normal must still face up.
  d.vertices = {-h * Vector3d::UnitX() - h * along, -h * Vector3d::UnitX() + h * along,
                h * Vector3d::UnitX() + h * along, h * Vector3d::UnitX() - h * along};
  d.triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto mesh = makeTerrain(d);
  const PlaneTerrain plane(Vector3d::Zero(), n);
  // Steep enough rays from above the square's middle that all land on it.
  for (const Ray& r : downwardRays(300, 10, 6, 3, 0.4))
    expectSameHit(mesh->castRay(r.from, r.direction, 60), plane.castRay(r.from, r.direction, 60), "tilted");
}

TEST(BulletTerrain, RaysThatMissReportNoHit) {
  const auto mesh = makeTerrain(flatSquareMesh(10, 0));
  const auto field = makeTerrain(flatHeightfield(11, 11, -5, -5, 1, 0));
  for (const Terrain* t : {mesh.get(), field.get()}) {
    EXPECT_FALSE(t->castRay({0, 0, 1}, {0, 0, 1}, 10).hit);      // pointing away
    EXPECT_FALSE(t->castRay({0, 0, 1}, {0, 0, -1}, 0.5).hit);    // too short
    EXPECT_FALSE(t->castRay({30, 0, 1}, {0, 0, -1}, 10).hit);    // beside the surface
    EXPECT_FALSE(t->castRay({0, 0, 1}, {0, 0, 0}, 10).hit);      // no direction
    EXPECT_FALSE(t->castRay({0, NAN, 1}, {0, 0, -1}, 10).hit);   // not a number
    EXPECT_FALSE(t->castRay({0, 0, 1}, {0, 0, -1}, -1).hit);     // negative length
    EXPECT_TRUE(t->castRay({0.3, 0.2, 1}, {0, 0, -1}, 10).hit);  // and the same terrain does hit
  }
}

// ---------------------------------------------------------------------------
// Generated roads against their analytic shapes.

// Rays straight down over [xLo, xHi] x [yLo, yHi] through a mesh's plan-view
// grid against Bullet's tree walk (a second algorithm), bit for bit; on grid
// lines (multiples of `snap`) as often as between them: the ties, which fall
// to the lowest triangle index whatever the order. Returns the hits.
int expectGridHitsWhatTheTreeHits(const TerrainData& d, double xLo, double xHi, double yLo, double yHi, double snap,
                                  const std::function<void(const Eigen::Vector3d&, const Hit&)>& alsoCheck = {}) {
  const std::unique_ptr<Terrain> grid = makeMeshTerrain(d), tree = makeMeshTerrain(d, false);
  EXPECT_TRUE(hasPlanGrid(*grid));
  EXPECT_FALSE(hasPlanGrid(*tree));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int hits = 0;
  for (int k = 0; k < 20000; ++k) {
    double x = xLo + (xHi - xLo) * u(rng), y = yLo + (yHi - yLo) * u(rng);
    if (k % 3 == 0) x = snap * std::round(x / snap);
    if (k % 5 == 0) y = snap * std::round(y / snap);
    const Eigen::Vector3d from(x, y, k % 2 ? 5.0 : 1.0);
    const Eigen::Vector3d down(0, 0, -1);
    const Hit a = grid->castRay(from, down, 8.0), e = tree->castRay(from, down, 8.0);
    EXPECT_EQ(a.hit, e.hit) << x << ", " << y;
    if (a.hit != e.hit) return hits;
    if (!a.hit) continue;
    ++hits;
    EXPECT_EQ(a.distance, e.distance) << x << ", " << y;
    EXPECT_EQ(a.point, e.point) << x << ", " << y;
    EXPECT_EQ(a.normal, e.normal) << x << ", " << y;
    if (a.point != e.point || a.normal != e.normal) return hits;
    if (alsoCheck) alsoCheck(from, a);
  }
  return hits;
}

// A bumpy mesh with a step, a sliver, two layers (a deck over the road) and
// shared edges and vertices, its corner at (x0, y0).
TerrainData bumpyMeshWithDeckAndSliver(double x0, double y0) {
  TerrainData d;
  d.kind = TerrainKind::Mesh;
  const int n = 40;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      d.vertices.emplace_back(x0 + 0.5 * i, y0 + 0.5 * j, 0.05 * std::sin(0.7 * i) * std::cos(0.4 * j) + (i > 20 ? 0.12 : 0.0));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      d.triangles.push_back({a, a + 1, a + n + 2});
      d.triangles.push_back({a, a + n + 2, a + n + 1});
    }
  // A bridge deck 3 m above part of the road, and a sliver across it all.
  const int b = static_cast<int>(d.vertices.size());
  for (const auto& [x, y] : {std::pair{4.0, 4.0}, {12.0, 4.0}, {12.0, 6.0}, {4.0, 6.0}}) d.vertices.emplace_back(x0 + x, y0 + y, 3.0);
  d.triangles.push_back({b, b + 1, b + 2});
  d.triangles.push_back({b, b + 2, b + 3});
  const int s = static_cast<int>(d.vertices.size());
  d.vertices.emplace_back(x0 + 0.1, y0 + 10.0, 0.5);
  d.vertices.emplace_back(x0 + 19.9, y0 + 10.02, 0.5);
  d.vertices.emplace_back(x0 + 19.9, y0 + 10.0, 0.6);
  d.triangles.push_back({s, s + 1, s + 2});
  return d;
}

TEST(BulletTerrain, RaysDownThroughThePlanGridHitWhatTheTreeHits) {
  const TerrainData d = bumpyMeshWithDeckAndSliver(0, 0);
  const int hits = expectGridHitsWhatTheTreeHits(d, -1, 21, -1, 21, 0.5, [](const Eigen::Vector3d& from, const Hit& a) {
    // Over the deck from above it: the deck; from under it: the road.
    if (from.x() > 4.1 && from.x() < 11.9 && from.y() > 4.1 && from.y() < 5.9) {
      if (from.z() > 3.0) EXPECT_EQ(a.point.z(), 3.0) << from.transpose();
      else EXPECT_LT(a.point.z(), 0.5) << from.transpose();
    }
  });
  EXPECT_GT(hits, 15000);
}

// The same mesh kilometres from its origin, where Bullet's single precision
// rounds the corners and the ray to millimetres: the grid skips a triangle
// only where the tree's test rejects it too (the plan-view margins).
TEST(BulletTerrain, RaysDownThroughThePlanGridFarFromTheOriginHitWhatTheTreeHits) {
  const double x0 = 6000.0, y0 = -3500.0;
  const TerrainData d = bumpyMeshWithDeckAndSliver(x0, y0);
  EXPECT_GT(expectGridHitsWhatTheTreeHits(d, x0 - 1, x0 + 21, y0 - 1, y0 + 21, 0.5), 15000);
}

// A road meshed in strips across its whole width (the washboard asset: ridges
// 9 cm apart on a 20 m wide road), whose grid cells are a strip long and the
// road wide: the same hits as the tree, the ridges' edges included.
TEST(BulletTerrain, RaysDownOnARoadOfStripsHitWhatTheTreeHits) {
  const TerrainData d = loadTerrain(assetPath("washboard.toml"));
  ASSERT_EQ(d.kind, TerrainKind::Mesh);
  EXPECT_GT(expectGridHitsWhatTheTreeHits(d, 25, 45, -9.9, 9.9, 0.0875), 19000);
}

TEST(RoadSurface, RampHeightAndNormalMatchAnalytic) {
  const double a = 8.0 * std::numbers::pi / 180.0, top = 0.5, foot = 10.0;
  RoadSurface road{.xMin = 0, .xMax = 30, .yMin = -5, .yMax = 5};
  road.ramps.push_back({.x = foot, .angle = a, .height = top, .topLength = 2.0, .yMin = -2.0, .yMax = 2.0});
  const double topStart = foot + top / std::tan(a), lip = topStart + 2.0;
  const Vector3d slopeNormal(-std::sin(a), 0, std::cos(a));
  for (const bool asMesh : {true, false}) {
    const auto t = makeTerrain(built(road, asMesh));
    const std::string what = asMesh ? "mesh" : "heightfield";
    // Heightfield cells are 0.25 m: stay out of the cells the slope's top
    // edge and the ramp's sides bend (the mesh has grid lines there).
    for (double x = foot + 0.05; x < 13.5; x += 0.173)
      for (double y : {-1.9, -0.6, 0.0, 1.3, 1.7}) {
        const Hit h = t->castRay({x, y, 5}, {0, 0, -1}, 10);
        ASSERT_TRUE(h.hit) << what;
        EXPECT_NEAR(h.point.z(), (x - foot) * std::tan(a), kTol) << what << " x=" << x;
        expectNear(h.normal, slopeNormal, kTol, what + " slope normal");
      }
    EXPECT_NEAR(heightUnder(*t, 15.0, 0.0), top, kTol) << what;  // on the top
    EXPECT_NEAR(heightUnder(*t, 16.0, 0.0), 0.0, kTol) << what;  // past the lip
    EXPECT_NEAR(heightUnder(*t, 12.0, 3.0), 0.0, kTol) << what;  // beside the ramp
  }
  // The mesh's lip is a vertical wall: a ray flying back along -x meets it at x = lip.
  const auto mesh = makeTerrain(built(road, true));
  const Hit wall = mesh->castRay({20, 0.5, 0.25}, {-1, 0, 0}, 10);
  ASSERT_TRUE(wall.hit);
  EXPECT_NEAR(wall.point.x(), lip, kTol);
  expectNear(wall.normal, {1, 0, 0}, kTol, "lip normal");
}

TEST(RoadSurface, StepBumpProfileAndFaces) {
  RoadSurface road{.xMin = -10, .xMax = 10, .yMin = -5, .yMax = 5};
  road.bumps.push_back({.profile = Bump::Profile::Step, .x = 5.0, .length = 0.5, .height = 0.1, .yMin = 0.0, .yMax = 2.0});
  const auto t = makeTerrain(built(road, true));
  const std::vector<std::pair<double, double>> profile = {
      {4.99, 0.0}, {5.001, 0.1}, {5.25, 0.1}, {5.499, 0.1}, {5.501, 0.0}, {8.0, 0.0}};
  for (const auto& [x, z] : profile) EXPECT_NEAR(heightUnder(*t, x, 1.0), z, kTol) << "x=" << x;
  EXPECT_NEAR(heightUnder(*t, 5.25, -0.01), 0.0, kTol);  // just beside it
  EXPECT_NEAR(heightUnder(*t, 5.25, 0.01), 0.1, kTol);
  // The faces are vertical and face out of the bump.
  const Hit front = t->castRay({4, 1, 0.05}, {1, 0, 0}, 5);
  ASSERT_TRUE(front.hit);
  EXPECT_NEAR(front.point.x(), 5.0, kTol);
  expectNear(front.normal, {-1, 0, 0}, kTol, "front face");
  const Hit side = t->castRay({5.25, 3, 0.05}, {0, -1, 0}, 5);
  ASSERT_TRUE(side.hit);
  EXPECT_NEAR(side.point.y(), 2.0, kTol);
  expectNear(side.normal, {0, 1, 0}, kTol, "side face");
}

TEST(RoadSurface, CosineBumpProfileWithinSamplingError) {
  const double height = 0.08, length = 1.2, cell = 0.05;
  RoadSurface road{.xMin = -5, .xMax = 5, .yMin = -3, .yMax = 3, .cell = cell};
  road.bumps.push_back({.profile = Bump::Profile::Cosine, .x = -0.6, .length = length, .height = height});
  // Linear interpolation of h(x) = H/2 (1 - cos(2 pi (x - x0) / L)) between
  // samples at most `cell` apart errs by at most max|h''| cell^2 / 8.
  const double bound = 0.5 * height * std::pow(2 * std::numbers::pi / length, 2) * cell * cell / 8;
  for (const bool asMesh : {true, false}) {
    const auto t = makeTerrain(built(road, asMesh));
    for (double x = -0.8; x <= 0.8; x += 0.0137) {
      const double exact = std::abs(x) < 0.6 ? 0.5 * height * (1 - std::cos(2 * std::numbers::pi * (x + 0.6) / length)) : 0;
      EXPECT_NEAR(heightUnder(*t, x, 0.7), exact, bound + kTol) << (asMesh ? "mesh" : "heightfield") << " x=" << x;
    }
    EXPECT_NEAR(heightUnder(*t, 0.0, -1.0), height, bound + kTol);
  }
}

TEST(RoadSurface, RoughRoadIsSeededAndHasTheRequestedRms) {
  const RoadSurface a = roughRoad(7, 0.1), b = roughRoad(7, 0.1), c = roughRoad(8, 0.1);
  const TerrainData ha = built(a, false), hb = built(b, false), hc = built(c, false);
  EXPECT_EQ(ha.heights, hb.heights);  // same seed: bit-identical
  EXPECT_NE(ha.heights, hc.heights);  // another seed: another road
  // RMS over the fully rough part (x in [4, 36]) against the requested 0.02 m.
  double sum = 0;
  int n = 0;
  for (int row = 0; row < ha.rows; ++row)
    for (int col = 0; col < ha.cols; ++col) {
      const double x = ha.x0 + col * ha.dx;
      if (x < 4 || x > 36) continue;
      sum += std::pow(ha.heights[static_cast<std::size_t>(row) * ha.cols + col], 2);
      ++n;
    }
  EXPECT_NEAR(std::sqrt(sum / n), 0.02, 0.2 * 0.02);
  EXPECT_EQ(roadHeight(a, 1.0, 0.0), 0.0);   // flat before the patch
  EXPECT_EQ(roadHeight(a, 39.0, 0.0), 0.0);  // and after it
}

// ---------------------------------------------------------------------------
// Heightfield and mesh of one shape; drawn triangles against queried surface.

TEST(BulletTerrain, HeightfieldAndMeshOfTheSameRoughRoadAgree) {
  const RoadSurface road = roughRoad(11, 0.2);
  const TerrainData field = built(road, false);
  const auto hf = makeTerrain(field);
  const auto mesh = makeTerrain(heightfieldAsMesh(field));
  // Rays of all slants (the long oblique ones cross many cells).
  std::vector<Ray> rays = downwardRays(2000, 4, 1, 5);
  for (Ray& r : rays) r.from.x() += 20;
  for (const Ray& r : rays) expectSameHit(hf->castRay(r.from, r.direction, 30), mesh->castRay(r.from, r.direction, 30), "rough");
  // At the grid nodes both carry the analytic height.
  for (int col = 3; col < field.cols; col += 17)
    for (int row = 1; row + 1 < field.rows; row += 7) {
      const double x = field.x0 + col * field.dx, y = field.y0 + row * field.dy;
      EXPECT_NEAR(heightUnder(*hf, x, y), roadHeight(road, x, y), kTol);
      EXPECT_NEAR(heightUnder(*mesh, x, y), roadHeight(road, x, y), kTol);
    }
}

TEST(TerrainMesh, DrawnTrianglesAreTheQueriedSurface) {
  const TerrainData field = built(roughRoad(3, 0.25), false);
  const auto hf = makeTerrain(field);
  const TriangleMesh drawn = triangulate(field);
  EXPECT_EQ(drawn.triangles.size(), 2u * (field.rows - 1) * (field.cols - 1));
  for (std::size_t i = 0; i < drawn.triangles.size(); i += 37) {
    const auto& t = drawn.triangles[i];
    const Vector3d a = drawn.vertices[t[0]], b = drawn.vertices[t[1]], c = drawn.vertices[t[2]];
    EXPECT_GT((b - a).cross(c - a).z(), 0.0);  // counter-clockwise seen from above
    const Vector3d centroid = (a + b + c) / 3;
    const Hit h = hf->castRay(centroid + Vector3d(0, 0, 1), {0, 0, -1}, 2);
    ASSERT_TRUE(h.hit);
    expectNear(h.point, centroid, kTol, "centroid");
    expectNear(h.normal, (b - a).cross(c - a).normalized(), kTol, "face normal");
  }
  for (const Vector3d& n : drawn.normals) EXPECT_NEAR(n.norm(), 1.0, 1e-12);
}

TEST(TerrainMesh, PlaneBecomesASquareAndCurbsStaySharp) {
  TerrainData plane;
  plane.planePoint = {1, 2, 3};
  plane.planeNormal = Vector3d(0, 0.6, 0.8);
  const TriangleMesh square = triangulate(plane, 100.0);
  ASSERT_EQ(square.vertices.size(), 4u);
  ASSERT_EQ(square.triangles.size(), 2u);
  for (const Vector3d& v : square.vertices) {
    EXPECT_NEAR((v - plane.planePoint).dot(plane.planeNormal), 0.0, 1e-9);
    EXPECT_NEAR((v - plane.planePoint).norm(), 100.0 * std::sqrt(2.0), 1e-9);
  }
  for (const auto& t : square.triangles) {
    const Vector3d n = (square.vertices[t[1]] - square.vertices[t[0]]).cross(square.vertices[t[2]] - square.vertices[t[0]]);
    EXPECT_GT(n.dot(plane.planeNormal), 0.0);
  }
  // A step bump: corners on its top edge are drawn twice, once facing up and
  // once facing out of the wall, so the edge stays sharp.
  RoadSurface road{.xMin = -2, .xMax = 2, .yMin = -2, .yMax = 2};
  road.bumps.push_back({.x = 0.0, .length = 0.5, .height = 0.1});
  const TriangleMesh m = triangulate(built(road, true));
  int up = 0, wall = 0;
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    if (std::abs(m.vertices[i].x()) < 1e-12 && std::abs(m.vertices[i].z() - 0.1) < 1e-12) {
      up += m.normals[i].isApprox(Vector3d::UnitZ(), 1e-12);
      wall += m.normals[i].isApprox(-Vector3d::UnitX(), 1e-12);
    }
  EXPECT_GT(up, 0);
  EXPECT_EQ(up, wall);
}

// ---------------------------------------------------------------------------
// The loader: good files.

TEST(TerrainFile, ObjQuadsAreSplitAndOffset) {
  writeFile("quad.obj",
            "# a 4 m square as one quad, z up\n"
            "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\n"
            "vn 0 0 1\n"
            "f 1//1 2//1 3//1 4//1\n");
  const std::string toml = writeFile("quad.toml",
                                     "kind = \"mesh\"\nfriction = 0.6\n[mesh]\nobj = \"quad.obj\"\n"
                                     "offset = [10.0, 0.0, 0.5]\n");
  const TerrainData d = loadTerrain(toml);
  EXPECT_EQ(d.kind, TerrainKind::Mesh);
  EXPECT_EQ(d.name, "quad");
  ASSERT_EQ(d.triangles.size(), 2u);
  const auto t = makeTerrain(d);
  const Hit h = t->castRay({13, 1, 2}, {0, 0, -1}, 5);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.point.z(), 0.5, kTol);
  EXPECT_EQ(h.friction, 0.6);
  EXPECT_FALSE(t->castRay({1, 1, 2}, {0, 0, -1}, 5).hit);  // moved away by the offset
}

TEST(TerrainFile, InlineHeightfieldRowsStepAlongY) {
  const std::string toml = writeFile("hf.toml",
                                     "kind = \"heightfield\"\nfriction = 1\n[heightfield]\n"
                                     "x0 = 1.0\ny0 = 2.0\ndx = 0.5\ndy = 2\n"
                                     "heights = [[0.0, 0.1, 0.2], [1.0, 2.0, 1.2]]\n");
  const TerrainData d = loadTerrain(toml);
  ASSERT_EQ(d.rows, 2);
  ASSERT_EQ(d.cols, 3);
  const auto t = makeTerrain(d);
  EXPECT_NEAR(heightUnder(*t, 1.5, 2.0), 0.1, kTol);    // row 0, col 1
  EXPECT_NEAR(heightUnder(*t, 1.5, 3.0), 1.05, kTol);   // halfway to row 1, col 1 (2.0)
  // The centre of cell (0, 0) lies on its (0,0)-(1,1) diagonal: the mean of
  // 0.0 and 2.0 (the other diagonal would give the mean of 0.1 and 1.0).
  EXPECT_NEAR(heightUnder(*t, 1.25, 3.0), 1.0, kTol);
}

// ---------------------------------------------------------------------------
// The loader: bad files name the file, the line, the key and what was expected.

TEST(TerrainFile, MissingKeyNamesFileAndKey) {
  const std::string m = loadError("missing.toml", "kind = \"plane\"\nname = \"x\"\n");
  EXPECT_TRUE(contains(m, "missing.toml")) << m;
  EXPECT_TRUE(contains(m, "missing key 'friction'")) << m;
  EXPECT_TRUE(contains(m, "(0, 2]")) << m;
  const std::string sub = loadError("missing_sub.toml", "kind = \"road\"\nfriction = 0.9\n[surface]\nx_min = 0\nx_max = 10\ny_min = -1\n");
  EXPECT_TRUE(contains(sub, "missing_sub.toml:3:")) << sub;  // the [surface] header
  EXPECT_TRUE(contains(sub, "missing key 'surface.y_max'")) << sub;
}

TEST(TerrainFile, WrongTypeNamesLineKeyAndType) {
  const std::string m = loadError("type.toml", "kind = \"plane\"\nfriction = \"high\"\n");
  EXPECT_TRUE(contains(m, "type.toml:2:")) << m;
  EXPECT_TRUE(contains(m, "key 'friction': expected a number in (0, 2], got \"high\"")) << m;
  const std::string v = loadError("vec.toml", "kind = \"plane\"\nfriction = 0.9\n[plane]\nnormal = [0, 1]\n");
  EXPECT_TRUE(contains(v, "vec.toml:4:")) << v;
  EXPECT_TRUE(contains(v, "key 'plane.normal': expected 3 components [x, y, z], got 2")) << v;
}

TEST(TerrainFile, OutOfRangeNamesLineKeyAndRange) {
  const std::string m = loadError("range.toml", "kind = \"plane\"\nfriction = 5.0\n");
  EXPECT_TRUE(contains(m, "range.toml:2:")) << m;
  EXPECT_TRUE(contains(m, "key 'friction': expected a number in (0, 2], got 5")) << m;
  const std::string b = loadError("bump.toml",
                                  "kind = \"road\"\nfriction = 0.9\n[surface]\nx_min = 0\nx_max = 10\ny_min = -1\n"
                                  "y_max = 1\n[[bumps]]\nx = 2\nlength = -0.5\nheight = 0.1\n");
  EXPECT_TRUE(contains(b, "bump.toml:10:")) << b;
  EXPECT_TRUE(contains(b, "key 'bumps[0].length': expected a number in (0, 10000], got -0.5")) << b;
  const std::string order = loadError("order.toml",
                                      "kind = \"road\"\nfriction = 0.9\n[surface]\nx_min = 10\nx_max = 0\n"
                                      "y_min = -1\ny_max = 1\n");
  EXPECT_TRUE(contains(order, "order.toml:5:")) << order;
  EXPECT_TRUE(contains(order, "key 'surface.x_max': expected a number greater than x_min")) << order;
  // A grid too large to build is refused before anything is allocated.
  const std::string huge = loadError("huge.toml",
                                     "kind = \"road\"\nfriction = 0.9\nbuild = \"mesh\"\n[surface]\nx_min = 0\n"
                                     "x_max = 100000\ny_min = -10\ny_max = 10\ncell = 0.0001\n[[rough]]\nseed = 1\n"
                                     "x_min = 0\nx_max = 100000\nrms_height = 0.01\n");
  EXPECT_TRUE(contains(huge, "huge.toml:9:")) << huge;
  EXPECT_TRUE(contains(huge, "key 'surface.cell': gives too large a grid")) << huge;
}

TEST(TerrainFile, UnknownKeysAreErrors) {
  const std::string m = loadError("unknown.toml", "kind = \"plane\"\nfriction = 0.9\nfrction = 0.8\n");
  EXPECT_TRUE(contains(m, "unknown.toml:3:")) << m;
  EXPECT_TRUE(contains(m, "unknown key 'frction'")) << m;
  const std::string sub = loadError("unknown_sub.toml",
                                    "kind = \"road\"\nfriction = 0.9\n[surface]\nx_min = 0\nx_max = 10\ny_min = -1\n"
                                    "y_max = 1\ncel = 0.1\n");
  EXPECT_TRUE(contains(sub, "unknown_sub.toml:8:")) << sub;
  EXPECT_TRUE(contains(sub, "unknown key 'surface.cel'")) << sub;
  // A table of another kind is unknown too.
  const std::string other = loadError("other.toml", "kind = \"plane\"\nfriction = 0.9\n[mesh]\nobj = \"a.obj\"\n");
  EXPECT_TRUE(contains(other, "other.toml:3:")) << other;
  EXPECT_TRUE(contains(other, "unknown key 'mesh'")) << other;
  const std::string kind = loadError("kind.toml", "kind = \"lava\"\nfriction = 0.9\n");
  EXPECT_TRUE(contains(kind, "kind.toml:1:")) << kind;
  EXPECT_TRUE(contains(kind, "key 'kind': expected one of \"plane\", \"mesh\", \"heightfield\", \"road\", \"track\", \"ground\", got \"lava\"")) << kind;
}

TEST(TerrainFile, MissingOrBrokenObjNamesBothFiles) {
  const std::string m = loadError("noobj.toml", "kind = \"mesh\"\nfriction = 0.9\n[mesh]\nobj = \"nothere.obj\"\n");
  EXPECT_TRUE(contains(m, "noobj.toml:4:")) << m;
  EXPECT_TRUE(contains(m, "key 'mesh.obj'")) << m;
  EXPECT_TRUE(contains(m, "nothere.obj")) << m;
  EXPECT_TRUE(contains(m, "does not exist")) << m;
  writeFile("broken.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  const std::string b = loadError("broken.toml", "kind = \"mesh\"\nfriction = 0.9\n[mesh]\nobj = \"broken.obj\"\n");
  EXPECT_TRUE(contains(b, "broken.toml:4:")) << b;
  EXPECT_TRUE(contains(b, "broken.obj:3:")) << b;
  EXPECT_TRUE(contains(b, "vertex index 3 out of range")) << b;
  writeFile("nan.obj", "v 0 0 zero\n");
  const std::string n = loadError("nan.toml", "kind = \"mesh\"\nfriction = 0.9\n[mesh]\nobj = \"nan.obj\"\n");
  EXPECT_TRUE(contains(n, "nan.obj:1:")) << n;
  EXPECT_TRUE(contains(n, "expected a finite number, got 'zero'")) << n;
}

TEST(TerrainFile, BrokenTomlAndRaggedRowsAreReported) {
  const std::string s = loadError("syntax.toml", "kind = \"plane\"\nfriction = [0.9,\n");
  EXPECT_TRUE(contains(s, "syntax.toml:3:")) << s;  // where toml11 finds the array unfinished
  EXPECT_TRUE(contains(s, "syntax error")) << s;
  const std::string r = loadError("ragged.toml",
                                  "kind = \"heightfield\"\nfriction = 0.9\n[heightfield]\ndx = 1\ndy = 1\n"
                                  "heights = [\n  [0, 0, 0],\n  [0, 0],\n]\n");
  EXPECT_TRUE(contains(r, "ragged.toml:8:")) << r;
  EXPECT_TRUE(contains(r, "key 'heightfield.heights': expected rows of 3 numbers like the first, got an array of 2 elements")) << r;
  try {
    loadTerrain((scratchDir() / "absent.toml").string());
    ADD_FAILURE() << "no error for a missing file";
  } catch (const TerrainFileError& e) {
    EXPECT_TRUE(contains(e.what(), "absent.toml")) << e.what();
    EXPECT_TRUE(contains(e.what(), "not found")) << e.what();
  }
}

// ---------------------------------------------------------------------------
// The shipped assets and their documented layout.

TEST(TerrainAssets, FlatRoadCoversTheRunAndTheLaneChange) {
  const TerrainData d = loadTerrain(assetPath("flat.toml"));
  const auto t = makeTerrain(d);
  EXPECT_EQ(d.kind, TerrainKind::Plane);
  EXPECT_NEAR(heightUnder(*t, 0, -1.75), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 80.0 / 3.6 * 7.0, -1.75), 0.0, kTol);
  ASSERT_TRUE(d.road.present);
  EXPECT_LE(d.road.startX, 0.0);
  EXPECT_GE(d.road.endX, 210.0 + 50.0);  // the ISO course from x = 100 plus a run-out
  EXPECT_EQ(d.road.lanes, 2);
  EXPECT_DOUBLE_EQ(d.road.laneWidth, 3.5);
}

TEST(TerrainAssets, CurbHasItsBlockAndKerb) {
  const auto t = makeTerrain(loadTerrain(assetPath("curb.toml")));
  EXPECT_NEAR(heightUnder(*t, 29.9, -1.0), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 30.25, -1.0), 0.10, kTol);   // left wheel track of the right lane
  EXPECT_NEAR(heightUnder(*t, 30.25, -2.5), 0.0, kTol);    // right wheel track passes beside it
  EXPECT_NEAR(heightUnder(*t, 100.0, -5.0), 0.10, kTol);   // sidewalk
  EXPECT_NEAR(heightUnder(*t, 100.0, -3.0), 0.0, kTol);    // road
  // The sidewalk's top triangles are 190 m long: its ends still stop sharply.
  EXPECT_NEAR(heightUnder(*t, 60.0 - 1e-5, -5.0), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 60.0 + 1e-5, -5.0), 0.10, kTol);
  EXPECT_NEAR(heightUnder(*t, 250.0 + 1e-5, -5.0), 0.0, kTol);
  const Hit kerb = t->castRay({100, -2, 0.05}, {0, -1, 0}, 5);
  ASSERT_TRUE(kerb.hit);
  EXPECT_NEAR(kerb.point.y(), -3.5, kTol);
  expectNear(kerb.normal, {0, 1, 0}, kTol, "kerb face");
}

TEST(TerrainAssets, RampRisesAtEightDegreesToHalfAMetre) {
  const auto t = makeTerrain(loadTerrain(assetPath("ramp.toml")));
  const double a = 8.0 * std::numbers::pi / 180.0, lip = 50.0 + 0.5 / std::tan(a);
  EXPECT_NEAR(heightUnder(*t, 49.0, 0.0), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 52.0, 0.0), 2.0 * std::tan(a), kTol);
  EXPECT_NEAR(heightUnder(*t, lip - 1e-6, -1.75), 0.5, 1e-6);
  EXPECT_NEAR(heightUnder(*t, lip + 1e-6, -1.75), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 52.0, 4.0), 0.0, kTol);  // beside the ramp
}

TEST(TerrainAssets, RoughRoadIsRoughOnlyInTheMiddle) {
  const TerrainData d = loadTerrain(assetPath("rough.toml"));
  EXPECT_EQ(d.kind, TerrainKind::Heightfield);
  const auto t = makeTerrain(d);
  EXPECT_NEAR(heightUnder(*t, 10.0, -1.75), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 210.0, -1.75), 0.0, kTol);
  double sum = 0;
  int n = 0;
  for (double x = 30; x < 190; x += 0.37) {
    sum += std::pow(heightUnder(*t, x, -1.75), 2) + std::pow(heightUnder(*t, x, 1.75), 2);
    n += 2;
  }
  const double rms = std::sqrt(sum / n);
  EXPECT_GT(rms, 0.005);  // documented RMS 0.010 m; one track is a small sample
  EXPECT_LT(rms, 0.02);
}

TEST(TerrainAssets, PotholeUnderTheRightWheelsOnly) {
  const auto t = makeTerrain(loadTerrain(assetPath("pothole.toml")));
  EXPECT_NEAR(heightUnder(*t, 30.4, -2.55), -0.06, kTol);  // right wheel track, in the hole
  EXPECT_NEAR(heightUnder(*t, 30.4, -0.95), 0.0, kTol);    // left wheel track beside it
  EXPECT_NEAR(heightUnder(*t, 29.9, -2.55), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 30.9, -2.55), 0.0, kTol);
}

TEST(TerrainAssets, WashboardRidgesHaveTheirWavelengthAndHeight) {
  // height/2 (1 - cos(2 pi (x - 30) / 0.7)) between the fades: crests of
  // 2 cm at 30 + 0.35 + 0.7 k, troughs of 0 at 30 + 0.7 k; the mesh keeps at
  // least 8 lines a wavelength, so its chords sit within h/2 (1 - cos(pi/8))
  // = 0.76 mm of the profile.
  const auto t = makeTerrain(loadTerrain(assetPath("washboard.toml")));
  const double chord = 0.01 * (1.0 - std::cos(std::numbers::pi / 8.0));
  for (int k = 10; k < 200; k += 37) {
    EXPECT_NEAR(heightUnder(*t, 30.35 + 0.7 * k, -1.75), 0.02, chord) << "crest " << k;
    EXPECT_NEAR(heightUnder(*t, 30.0 + 0.7 * k, 1.0), 0.0, chord) << "trough " << k;
  }
  EXPECT_NEAR(heightUnder(*t, 20.0, -1.75), 0.0, kTol);
  EXPECT_NEAR(heightUnder(*t, 240.0, -1.75), 0.0, kTol);
}

TEST(TerrainAssets, MuSplitHasTheSlipperyPatchOnTheRight) {
  const auto t = makeTerrain(loadTerrain(assetPath("mu_split.toml")));
  const Hit left = t->castRay({50, -1.0, 1}, {0, 0, -1}, 5), right = t->castRay({50, -2.5, 1}, {0, 0, -1}, 5);
  ASSERT_TRUE(left.hit && right.hit);
  EXPECT_DOUBLE_EQ(left.friction, 0.9);
  EXPECT_DOUBLE_EQ(right.friction, 0.2);
  EXPECT_NEAR(right.point.z(), 0.0, kTol);  // the patch changes the friction, not the surface
}

TEST(TerrainFile, BadFrictionPatchesAndCorrugationsNameTheirKey) {
  const std::string p = loadError("patch.toml", "kind = \"plane\"\nfriction = 0.9\n[[friction_patches]]\nx_min = 5.0\nx_max = 1.0\nfriction = 0.2\n");
  EXPECT_TRUE(contains(p, "patch.toml:5:")) << p;
  EXPECT_TRUE(contains(p, "key 'friction_patches[0].x_max': expected a number greater than x_min")) << p;
  const std::string c = loadError("corrugation.toml", "kind = \"road\"\nfriction = 0.9\n[surface]\nx_min = 0.0\nx_max = 10.0\ny_min = -1.0\ny_max = 1.0\n[[corrugations]]\nx_min = 1.0\nx_max = 9.0\nwavelength = 0.0\nheight = 0.02\n");
  EXPECT_TRUE(contains(c, "corrugation.toml:11:")) << c;
  EXPECT_TRUE(contains(c, "wavelength")) << c;
}

TEST(TerrainFile, FrictionPatchesApplyToEveryKindAndTheLastOneWins) {
  for (const char* kind : {"plane", "road"}) {
    const std::string body = std::string("kind = \"") + kind + "\"\nfriction = 0.8\n" +
                             (std::string(kind) == "road" ? "[surface]\nx_min = -10.0\nx_max = 10.0\ny_min = -10.0\ny_max = 10.0\n"
                                                          : "") +
                             "[[friction_patches]]\nx_min = 0.0\nfriction = 0.5\n"
                             "[[friction_patches]]\nx_min = 2.0\nx_max = 3.0\ny_max = 0.0\nfriction = 0.3\n";
    const std::string file = writeFile(std::string("patches_") + kind + ".toml", body);
    const auto t = makeTerrain(loadTerrain(file));
    auto mu = [&](double x, double y) { return t->castRay({x, y, 1}, {0, 0, -1}, 5).friction; };
    EXPECT_DOUBLE_EQ(mu(-1.0, 0.0), 0.8) << kind;
    EXPECT_DOUBLE_EQ(mu(1.0, 0.0), 0.5) << kind;
    EXPECT_DOUBLE_EQ(mu(2.5, -1.0), 0.3) << kind;  // inside both: the last listed
    EXPECT_DOUBLE_EQ(mu(2.5, 1.0), 0.5) << kind;
  }
}

// ---------------------------------------------------------------------------
// Determinism, concurrent reads, no allocation per ray.

namespace {
// One terrain of each kind, from the shipped assets.
std::vector<std::unique_ptr<Terrain>> assetTerrains() {
  std::vector<std::unique_ptr<Terrain>> out;
  for (const char* name : {"flat.toml", "curb.toml", "rough.toml"}) out.push_back(makeTerrain(loadTerrain(assetPath(name))));
  return out;
}

std::vector<Ray> roadRays(int n) {
  std::vector<Ray> rays = downwardRays(n, 3, 1, 9);
  for (Ray& r : rays) r.from.x() += 31;  // over the curb block and the rough patch
  return rays;
}
}  // namespace

TEST(TerrainDeterminism, SameQueryAndSameFileGiveTheSameBits) {
  const auto first = assetTerrains(), second = assetTerrains();
  for (std::size_t k = 0; k < first.size(); ++k)
    for (const Ray& r : roadRays(300)) {
      const Hit a = first[k]->castRay(r.from, r.direction, 5);
      EXPECT_TRUE(sameBits(a, first[k]->castRay(r.from, r.direction, 5)));   // the same query twice
      EXPECT_TRUE(sameBits(a, second[k]->castRay(r.from, r.direction, 5)));  // a terrain loaded again
    }
}

TEST(TerrainDeterminism, ConcurrentReadersSeeWhatOneReaderSees) {
  const auto terrains = assetTerrains();
  const std::vector<Ray> rays = roadRays(2000);
  for (const auto& t : terrains) {
    std::vector<Hit> serial, a(rays.size()), b(rays.size());
    for (const Ray& r : rays) serial.push_back(t->castRay(r.from, r.direction, 5));
    auto run = [&](std::vector<Hit>& out) {
      for (std::size_t i = 0; i < rays.size(); ++i) out[i] = t->castRay(rays[i].from, rays[i].direction, 5);
    };
    std::thread ta(run, std::ref(a)), tb(run, std::ref(b));
    ta.join();
    tb.join();
    for (std::size_t i = 0; i < rays.size(); ++i) {
      EXPECT_TRUE(sameBits(serial[i], a[i]));
      EXPECT_TRUE(sameBits(serial[i], b[i]));
    }
  }
}

TEST(TerrainDeterminism, RaysAllocateNoHeapMemory) {
#if !BDFCAR_ALLOCATION_COUNTERS
  GTEST_SKIP() << "allocation counters are off (sanitizer build: ASan owns malloc)";
#else
  const auto terrains = assetTerrains();
  const std::vector<Ray> rays = roadRays(1000);
  for (const auto& t : terrains) {
    int hits = 0;
    const long before = gAllocations.load();
    for (const Ray& r : rays) hits += t->castRay(r.from, r.direction, 5).hit;
    const long allocations = gAllocations.load() - before;
    EXPECT_EQ(allocations, 0);
    EXPECT_GT(hits, 900);
  }
  // The counter does see allocations (so the zero above means something).
  void* (*volatile allocate)(std::size_t) = std::malloc;
  const long before = gAllocations.load();
  void* p = allocate(64);
  std::free(p);
  EXPECT_EQ(gAllocations.load() - before, 1);
#endif
}
