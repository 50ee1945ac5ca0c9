// The kinematic rung derived from the linkage (physics/vehicle/kinematic_model):
// its tables against the linkage itself at configurations between the grid
// nodes, its mass against the linkage's, its static equilibrium against the
// linkage's, and what it leaves out (no loop constraints).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "multibody/multibody_dae.h"
#include "terrain/terrain.h"
#include "vehicle/equilibrium.h"
#include "vehicle/kinematic_model.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

class KinematicModel : public ::testing::TestWithParam<const char*> {};

TEST_P(KinematicModel, TablesReproduceTheLinkageBetweenTheNodes) {
  const vehicle::Vehicle link = vehicle::buildVehicle(vehicle::loadVehicleFile(asset(GetParam())));
  const vehicle::KinematicDerivation k = vehicle::deriveKinematic(link);
  std::printf("%s", vehicle::describeKinematic(k).c_str());
  EXPECT_GT(k.check.points, 20);
  // Tolerances: 0.1 mm and 0.1 mrad, far below what a tyre feels (a 0.1 mrad
  // toe error is a 0.1 mrad slip angle).
  EXPECT_LT(k.check.wheelCentre, 1e-4);
  EXPECT_LT(k.check.camber, 1e-4);
  EXPECT_LT(k.check.toe, 1e-4);
  EXPECT_GE(k.check.travelRange, 0.08);
  EXPECT_TRUE(k.steered[0] && k.steered[1]);
  EXPECT_FALSE(k.steered[2] || k.steered[3]);
}

TEST_P(KinematicModel, KeepsTheLinkagesMassAndDropsItsLoops) {
  const vehicle::Vehicle link = vehicle::buildVehicle(vehicle::loadVehicleFile(asset(GetParam())));
  const vehicle::KinematicDerivation k = vehicle::deriveKinematic(link);
  const vehicle::Vehicle& v = k.vehicle;
  EXPECT_EQ(v.fidelity, vehicle::Fidelity::Kinematic);
  EXPECT_NEAR(v.model.totalMass(), link.model.totalMass(), 1e-9 * link.model.totalMass());
  // Chassis 6, rack 1, four travels, two rack travels at the steered corners, four spins.
  EXPECT_EQ(v.model.nv, 6 + 1 + 4 + 2 + 4);
  EXPECT_EQ(v.model.nc, 3);  // the rack and the two corners' rack travel: drivers only
  for (int w = 0; w < 4; ++w) {
    EXPECT_GT(k.carrierMass[w], 0);
    EXPECT_LT(k.carrierMass[w], k.linkageTravelMass[w]);
  }
}

TEST_P(KinematicModel, SettlesWhereTheLinkageSettles) {
  const vehicle::Vehicle link = vehicle::buildVehicle(vehicle::loadVehicleFile(asset(GetParam())));
  const vehicle::KinematicDerivation k = vehicle::deriveKinematic(link);
  const terrain::PlaneTerrain flat;
  auto settle = [&](const vehicle::Vehicle& v) {
    mb::MultibodyDae dae(v.model);
    vehicle::VehicleForces forces(v, flat);
    dae.addForceProvider(&forces);
    integ::Vec q = vehicle::designPositions(v), lambda = integ::Vec::Zero(v.model.nc);
    return vehicle::settleStatic(v, dae, forces, 0.0, q, lambda);
  };
  const vehicle::EquilibriumReport a = settle(link), b = settle(k.vehicle);
  ASSERT_TRUE(a.converged) << a.message;
  ASSERT_TRUE(b.converged) << b.message;
  // The same weight on the same springs through the same geometry: the
  // links' inertia along travel through the carrier's mass, their weight
  // along travel through each corner's lumped weight (exact at design; the
  // car rests a millimetre from it). Without the lumped weight the sedan
  // rested 0.6 mm lower at the rear and 0.22 mrad more nose-down.
  std::printf("%s: chassis height %.3g m, pitch %.3g rad from the linkage's\n", GetParam(),
              b.chassisHeight - a.chassisHeight, b.pitch - a.pitch);
  EXPECT_NEAR(b.chassisHeight, a.chassisHeight, 2e-5);
  EXPECT_NEAR(b.pitch, a.pitch, 2e-5);
  for (int w = 0; w < 4; ++w) EXPECT_NEAR(b.wheelLoads[w], a.wheelLoads[w], 2e-3 * a.wheelLoads[w]) << w;
}

INSTANTIATE_TEST_SUITE_P(ReferenceVehicles, KinematicModel,
                         ::testing::Values("vehicles/sedan.toml", "vehicles/paper.toml"));

}  // namespace
}  // namespace bdfcar

namespace bdfcar {
namespace {

// The derivation cache (vehicle/derivation_cache.h): a second derivation
// reads the sweep from disk and gives the same model bit for bit; a corrupt
// entry is a miss (derived again, the same model); another vehicle has
// another key.
TEST(DerivationCache, GivesTheSameModelAndSurvivesACorruptEntry) {
  const std::string dir = (std::filesystem::temp_directory_path() / "bdfcar_derivation_cache_test").string();
  std::filesystem::remove_all(dir);
  ::setenv("BDFCAR_CACHE_DIR", dir.c_str(), 1);
  const vehicle::Vehicle link = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/sedan.toml")));
  const vehicle::KinematicDerivation fresh = vehicle::deriveKinematic(link);
  const vehicle::KinematicDerivation cached = vehicle::deriveKinematic(link);
  EXPECT_FALSE(fresh.fromCache);
  EXPECT_TRUE(cached.fromCache);
  ASSERT_TRUE(std::filesystem::exists(cached.cacheFile)) << cached.cacheFile;
  auto same = [](const vehicle::KinematicDerivation& a, const vehicle::KinematicDerivation& b) {
    EXPECT_EQ(a.carrierMass, b.carrierMass);
    EXPECT_EQ(a.check.wheelCentre, b.check.wheelCentre);
    EXPECT_EQ(a.check.toe, b.check.toe);
    EXPECT_EQ(a.sweepConfigurations, b.sweepConfigurations);
    ASSERT_EQ(a.vehicle.model.tables.size(), b.vehicle.model.tables.size());
    mb::SplineGrid::Sample sa, sb;
    for (size_t t = 0; t < a.vehicle.model.tables.size(); ++t)
      for (double s : {-0.1, -0.013, 0.0, 0.042, 0.11})
        for (double r : {-0.05, 0.0, 0.021}) {
          a.vehicle.model.tables[t].grid.eval(s, r, sa);
          b.vehicle.model.tables[t].grid.eval(s, r, sb);
          EXPECT_EQ(sa.f, sb.f);
          EXPECT_EQ(sa.grad, sb.grad);
        }
  };
  same(fresh, cached);
  // Flip a byte in the middle of the entry.
  {
    std::fstream f(cached.cacheFile, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(4000);
    char c = 0;
    f.get(c);
    f.seekp(4000);
    f.put(static_cast<char>(c ^ 0x40));
  }
  const vehicle::KinematicDerivation again = vehicle::deriveKinematic(link);
  EXPECT_FALSE(again.fromCache);
  same(fresh, again);
  // Truncated: a miss too.
  std::filesystem::resize_file(cached.cacheFile, 100);
  EXPECT_FALSE(vehicle::deriveKinematic(link).fromCache);
  const vehicle::Vehicle paper = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/paper.toml")));
  EXPECT_NE(vehicle::deriveKinematic(paper).cacheFile, cached.cacheFile);
  ::unsetenv("BDFCAR_CACHE_DIR");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace bdfcar
