// Cost of one terrain ray: 1 m straight down from 0.5 m above the ground, as
// a tyre query casts it, on the analytic plane, a Bullet heightfield and a
// Bullet triangle mesh of the same 200 m x 200 m rough ground with 1 m cells
// (80k triangles), and on the curb's and the washboard's road meshes.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "terrain/bullet/bullet_terrain.h"
#include "terrain/road_surface.h"
#include "terrain/terrain_file.h"
#include "terrain/terrain_mesh.h"

using namespace bdfcar::terrain;

namespace {

// 200 m x 200 m of gently rough ground sampled every metre.
TerrainData roughGround() {
  RoadSurface road{.xMin = -100, .xMax = 100, .yMin = -100, .yMax = 100, .cell = 1.0};
  RoughPatch p{.xMin = -100, .xMax = 100, .rmsHeight = 0.05, .wavelengthMin = 2.0, .wavelengthMax = 50.0};
  makeRoughWaves(p);
  road.rough.push_back(p);
  TerrainData d;
  buildRoadHeightfield(road, d);
  return d;
}

// Ray origins spread over the ground, 0.5 m above the highest bump of interest.
std::vector<Eigen::Vector3d> origins(double halfWidth, double z) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-halfWidth, halfWidth);
  std::vector<Eigen::Vector3d> out(4096);
  for (auto& o : out) o = {u(rng), u(rng), z};
  return out;
}

// One downward ray per iteration, cycling through the origins.
void castRays(benchmark::State& state, const Terrain& terrain, const std::vector<Eigen::Vector3d>& from) {
  std::size_t i = 0;
  int hits = 0;
  for (auto _ : state) {
    const Hit h = terrain.castRay(from[i], {0, 0, -1}, 1.0);
    benchmark::DoNotOptimize(h);
    hits += h.hit;
    i = (i + 1) % from.size();
  }
  state.counters["hit_fraction"] = benchmark::Counter(static_cast<double>(hits) / static_cast<double>(state.iterations()));
}

void BM_RayPlane(benchmark::State& state) {
  const PlaneTerrain plane;
  castRays(state, plane, origins(90, 0.5));
}

void BM_RayHeightfield(benchmark::State& state) {
  static const auto terrain = makeTerrain(roughGround());
  castRays(state, *terrain, origins(90, 0.5));
}

void BM_RayMesh(benchmark::State& state) {
  static const auto terrain = makeTerrain(heightfieldAsMesh(roughGround()));
  castRays(state, *terrain, origins(90, 0.5));
}

void BM_RayCurbAssetMesh(benchmark::State& state) {
  static const auto terrain = makeTerrain(loadTerrain(std::string(BDFCAR_ASSETS_DIR) + "/terrain/curb.toml"));
  std::vector<Eigen::Vector3d> from = origins(3.5, 0.5);
  for (auto& o : from) o.x() += 33.5;  // over the block, lane and kerb region x in [30, 37]
  castRays(state, *terrain, from);
}

// A road meshed in strips across its width: the washboard's ridges.
void BM_RayWashboardAssetMesh(benchmark::State& state) {
  static const auto terrain = makeTerrain(loadTerrain(std::string(BDFCAR_ASSETS_DIR) + "/terrain/washboard.toml"));
  std::vector<Eigen::Vector3d> from = origins(3.5, 0.5);
  for (auto& o : from) o.x() += 100.0;  // on the ridges, x in [30, 230]
  castRays(state, *terrain, from);
}

}  // namespace

BENCHMARK(BM_RayPlane);
BENCHMARK(BM_RayHeightfield);
BENCHMARK(BM_RayMesh);
BENCHMARK(BM_RayCurbAssetMesh);
BENCHMARK(BM_RayWashboardAssetMesh);
BENCHMARK_MAIN();
