// The planar rung derived from the linkage (physics/vehicle/planar_model):
// its mass, static loads and geometry against the linkage's, and what it
// leaves out (no loops, no springs, tables of the rack only). Its load
// transfer and handling against the linkage's: tests/test_scenario.cpp.
#include <gtest/gtest.h>

#include <cstdio>

#include "multibody/multibody_dae.h"
#include "terrain/terrain.h"
#include "vehicle/equilibrium.h"
#include "vehicle/planar_model.h"
#include "vehicle/vehicle_file.h"
#include "vehicle/vehicle_sheet.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

class PlanarModel : public ::testing::TestWithParam<const char*> {};

TEST_P(PlanarModel, KeepsTheLinkagesMassAndLoadsWithoutItsLoopsOrSprings) {
  const vehicle::Vehicle link = vehicle::buildVehicle(vehicle::loadVehicleFile(asset(GetParam())));
  const vehicle::PlanarDerivation p = vehicle::derivePlanar(link);
  std::printf("%s", vehicle::describePlanar(p).c_str());
  const vehicle::Vehicle& v = p.vehicle;
  EXPECT_EQ(v.fidelity, vehicle::Fidelity::Planar);
  ASSERT_TRUE(v.planar.has_value());
  EXPECT_NEAR(v.model.totalMass(), link.model.totalMass(), 1e-9 * link.model.totalMass());
  // Base 3, roll and pitch 2, rack 1, the steered corners' rack travel 2, four spins.
  EXPECT_EQ(v.model.nv, 3 + 2 + 1 + 2 + 4);
  EXPECT_EQ(v.model.nc, 3);
  EXPECT_TRUE(v.model.springs.empty());
  for (const mb::JointTable& t : v.model.tables) EXPECT_EQ(t.grid.dimensions(), 1);
  // Static loads: the linkage's own at rest on level ground.
  const terrain::PlaneTerrain flat;
  mb::MultibodyDae dae(link.model);
  vehicle::VehicleForces forces(link, flat);
  dae.addForceProvider(&forces);
  integ::Vec q = vehicle::designPositions(link), lambda = integ::Vec::Zero(link.model.nc);
  std::string msg;
  ASSERT_TRUE(vehicle::assemble(link, dae, 0.0, q, msg)) << msg;
  const vehicle::EquilibriumReport eq = vehicle::settleStatic(link, dae, forces, 0.0, q, lambda);
  ASSERT_TRUE(eq.converged) << eq.message;
  double total = 0;
  for (int w = 0; w < 4; ++w) {
    EXPECT_NEAR(v.planar->staticLoad[w], eq.wheelLoads[w], 2e-3 * eq.wheelLoads[w]) << w;
    total += v.planar->staticLoad[w];
  }
  EXPECT_NEAR(total, eq.weight, 1e-3 * eq.weight);
  // Tracks and wheelbase: the contact points against the file's geometry
  // (centimetres: camber and the static travel move the contact points).
  EXPECT_NEAR(v.planar->track[0], link.spec.geometry.trackFront, 0.02);
  EXPECT_NEAR(v.planar->track[1], link.spec.geometry.trackRear, 0.02);
  EXPECT_NEAR(v.planar->wheelbase, link.spec.geometry.wheelbase, 0.02);
  EXPECT_GT(v.planar->axisHeight, -0.2);
  EXPECT_LT(v.planar->axisHeight, eq.comHeight);
}

// The vehicle sheet: the static axle loads (the kinematic model's tyre loads
// at rest) balance the weight about the centre of mass (the bodies' mass
// properties): a moment balance the derivation does not use.
TEST_P(PlanarModel, SheetAxleLoadsBalanceTheWeightAboutTheCentreOfMass) {
  const vehicle::Vehicle link = vehicle::buildVehicle(vehicle::loadVehicleFile(asset(GetParam())));
  const vehicle::VehicleSheet s = vehicle::vehicleSheet(link);
  std::printf("%s", vehicle::describe(s).c_str());
  const double weight = s.mass * 9.81;
  EXPECT_NEAR(s.axleLoad[0] + s.axleLoad[1], weight, 1e-3 * weight);
  const double frontShare = (s.wheelbase - s.comBehindFrontAxle) / s.wheelbase;
  EXPECT_NEAR(s.axleLoad[0] / (s.axleLoad[0] + s.axleLoad[1]), frontShare, 2e-3);
  EXPECT_GT(s.steeringRatio, 1.0);
  EXPECT_GT(s.rideFrequency[0], 0.5);
  EXPECT_LT(s.rideFrequency[0], 5.0);
}

INSTANTIATE_TEST_SUITE_P(ReferenceVehicles, PlanarModel, ::testing::Values("vehicles/sedan.toml", "vehicles/paper.toml"));

}  // namespace
}  // namespace bdfcar
