// The kinematic rung derived from the linkage (physics/vehicle/kinematic_model):
// its tables against the linkage itself at configurations between the grid
// nodes, its mass against the linkage's, its static equilibrium against the
// linkage's, and what it leaves out (no loop constraints).
#include <gtest/gtest.h>

#include <cstdio>

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
  // The same weight on the same springs through the same geometry. The links'
  // inertia along travel is matched (the carrier's mass), their weight is not:
  // it hangs on the carrier and the chassis, not through the link geometry,
  // a few newtons per wheel, a fraction of a millimetre on the springs.
  EXPECT_NEAR(b.chassisHeight, a.chassisHeight, 5e-4);
  EXPECT_NEAR(b.pitch, a.pitch, 5e-4);
  for (int w = 0; w < 4; ++w) EXPECT_NEAR(b.wheelLoads[w], a.wheelLoads[w], 2e-3 * a.wheelLoads[w]) << w;
}

INSTANTIATE_TEST_SUITE_P(ReferenceVehicles, KinematicModel,
                         ::testing::Values("vehicles/sedan.toml", "vehicles/paper.toml"));

}  // namespace
}  // namespace bdfcar
