// Vehicle files, assembly and static equilibrium against the published
// figures of the reference sedan (docs/reference-vehicle.md), and the errors
// a bad vehicle file must give.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "config/toml_reader.h"
#include "multibody/constraints.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "terrain/terrain.h"
#include "vehicle/equilibrium.h"
#include "vehicle/motion_ratio.h"
#include "vehicle/vehicle_builder.h"
#include "test_files.h"
#include "vehicle/vehicle_file.h"

using namespace bdfcar;
using test::asset;
using test::sedanText;

namespace {

struct Settled {
  vehicle::Vehicle v;
  vehicle::EquilibriumReport eq;
  integ::Vec q;
};

Settled settle(const std::string& file) {
  Settled s{vehicle::buildVehicle(vehicle::loadVehicleFile(asset(file))), {}, {}};
  terrain::PlaneTerrain ground;
  vehicle::VehicleForces forces(s.v, ground);
  mb::MultibodyDae dae(s.v.model);
  dae.addForceProvider(&forces);
  s.q = vehicle::designPositions(s.v);
  std::string msg;
  EXPECT_TRUE(vehicle::assemble(s.v, dae, 0, s.q, msg)) << msg;
  integ::Vec lambda = integ::Vec::Zero(s.v.model.nc);
  s.eq = vehicle::settleStatic(s.v, dae, forces, 0, s.q, lambda);
  return s;
}

// Writes `text` to a temporary vehicle file next to the real assets (so that
// relative paths resolve the same way) and returns the loader's error.
std::string loadError(const std::string& text) {
  const std::string path = asset("vehicles/test_bad_vehicle.toml");
  {
    std::ofstream f(path);
    f << text;
  }
  std::string what;
  try {
    vehicle::buildVehicle(vehicle::loadVehicleFile(path));
  } catch (const std::exception& e) {
    what = e.what();
  }
  std::filesystem::remove(path);
  return what;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto i = s.find(from);
  EXPECT_NE(i, std::string::npos) << from;
  if (i != std::string::npos) s.replace(i, from.size(), to);
  return s;
}

}  // namespace

TEST(VehicleFile, PaperTopologyHasThePapersCounts) {
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/paper.toml")));
  const int spin = v.layout.spinCoordinates;
  EXPECT_EQ(spin, 4);
  EXPECT_EQ(v.model.nv - spin, 25);               // relative coordinates (Table 1)
  EXPECT_EQ(v.layout.cutJointEquations, 14);      // cut-joint constraints (Table 1)
  EXPECT_EQ(v.model.nv - spin - v.layout.cutJointEquations, 11);
}

TEST(VehicleFile, SedanIsTheReferenceVehicleJointForJoint) {
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/sedan.toml")));
  // docs/reference-vehicle.md 3: total mass 2422.30 kg, 20 bodies (chassis, rack, 2 x 4 front, 2 x 5 rear).
  EXPECT_NEAR(v.model.totalMass(), 2422.304, 1e-9);
  EXPECT_EQ(v.model.bodies.size(), 20u);
  // Front: LCA revolute, strut universal, upright cylindrical, spindle revolute.
  EXPECT_EQ(v.model.bodies[v.model.bodyIndex("strut_FL")].joint, mb::JointType::Universal);
  EXPECT_EQ(v.model.bodies[v.model.bodyIndex("upright_FL")].joint, mb::JointType::Cylindrical);
  EXPECT_EQ(v.model.bodies[v.model.bodyIndex("upright_RR")].joint, mb::JointType::Spherical);
  // Tie rods and toe links are massless distance constraints of the stated lengths.
  for (const mb::CutJoint& c : v.model.cutJoints) {
    if (c.name.rfind("tie_rod", 0) == 0) {
      EXPECT_DOUBLE_EQ(c.length, 0.382562);
    }
    if (c.name.rfind("toe_link", 0) == 0) {
      EXPECT_DOUBLE_EQ(c.length, 0.556896);
    }
  }
  // The mirrored right side is the left side with y -> -y.
  const auto& m = v.model;
  const mb::Body& l = m.bodies[m.bodyIndex("lca_FL")];
  const mb::Body& r = m.bodies[m.bodyIndex("lca_FR")];
  EXPECT_NEAR(l.inertia(0, 1), -r.inertia(0, 1), 1e-12);
  EXPECT_NEAR(l.inertia(0, 0), r.inertia(0, 0), 1e-12);
}

// The strut's top-mount axes written from hardpoints ("normal(...)" and a
// cross with the strut) are the ones docs/reference-vehicle.md 4.2 gives as
// numbers (5 digits), on the left and mirrored on the right.
TEST(VehicleFile, DirectionsFromHardpointsAreTheReferencesAxes) {
  const vehicle::VehicleSpec spec = vehicle::loadVehicleFile(asset("vehicles/sedan.toml"));
  const Eigen::Vector3d u(-0.52712, -0.81691, -0.23412), v(0.84120, -0.54067, -0.00743);
  int found = 0;
  for (const auto& b : spec.bodies) {
    if (b.name != "strut_FL" && b.name != "strut_FR") continue;
    const Eigen::Vector3d m = b.name == "strut_FL" ? Eigen::Vector3d(1, 1, 1) : Eigen::Vector3d(1, -1, 1);
    EXPECT_LT((b.joint.axisParent - m.cwiseProduct(u)).norm(), 1e-5) << b.name << ": " << b.joint.axisParent.transpose();
    // The child axis is a normal computed from the mirrored points: its sign may flip with the side.
    EXPECT_LT(std::min((b.joint.axisChild - m.cwiseProduct(v)).norm(), (b.joint.axisChild + m.cwiseProduct(v)).norm()), 1e-5)
        << b.name << ": " << b.joint.axisChild.transpose();
    ++found;
  }
  EXPECT_EQ(found, 2);
}

TEST(Assembly, ClosesTheLoopsFromADisturbedConfiguration) {
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/paper.toml")));
  mb::MultibodyDae dae(v.model);
  integ::Vec q = vehicle::designPositions(v), dq = integ::Vec::Zero(v.model.nv), qd(v.model.nq);
  // Move every suspension coordinate a little (loops open by millimetres).
  for (int i = 6; i < v.model.nv; ++i) dq(i) = 0.01 * std::sin(1.7 * i);
  mb::retract(v.model, q, dq, qd);
  mb::Data d = mb::makeData(v.model);
  mb::updatePositions(v.model, qd, d);
  mb::constraintPositions(v.model, qd, d);
  EXPECT_GT(d.phi.head(v.layout.cutJointEquations).lpNorm<Eigen::Infinity>(), 1e-3);
  std::string msg;
  ASSERT_TRUE(vehicle::assemble(v, dae, 0, qd, msg)) << msg;
  mb::updatePositions(v.model, qd, d);
  mb::constraintPositions(v.model, qd, d);
  EXPECT_LT(d.phi.head(v.layout.cutJointEquations).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(StaticEquilibrium, SedanMatchesThePublishedState) {
  const Settled s = settle("vehicles/sedan.toml");
  ASSERT_TRUE(s.eq.converged) << s.eq.message;
  // Wheel loads sum to the weight (vertical equilibrium).
  EXPECT_NEAR(s.eq.totalLoad, 2422.304 * 9.81, 1e-6 * s.eq.weight);
  // docs/reference-vehicle.md 11 (measured in Chrono at 80 km/h, where rolling
  // resistance and the 13.5 N m drive torque shift a few newtons; we settle at
  // rest): loads within 0.1 %, ride height and pitch within 0.02 mm / 0.002 deg.
  const double ref[4] = {6298.88, 6295.86, 5581.94, 5585.99};
  for (int w = 0; w < 4; ++w) EXPECT_NEAR(s.eq.wheelLoads[w], ref[w], 1e-3 * ref[w]) << "wheel " << w;
  EXPECT_NEAR(s.eq.chassisHeight, 0.51283, 2e-5);
  EXPECT_NEAR(s.eq.comHeight, 0.72636, 2e-5);
  EXPECT_NEAR(s.eq.pitch * 180 / M_PI, -0.555, 2e-3);
  EXPECT_NEAR(s.eq.roll, 0.0, 1e-9);
}

TEST(StaticEquilibrium, PaperTopologyCarriesTheSameLoads) {
  const Settled s = settle("vehicles/paper.toml");
  ASSERT_TRUE(s.eq.converged) << s.eq.message;
  EXPECT_NEAR(s.eq.totalLoad, s.eq.weight, 1e-6 * s.eq.weight);
  // Same masses and equivalent springs: the loads and the ride height of the sedan.
  const Settled ref = settle("vehicles/sedan.toml");
  for (int w = 0; w < 4; ++w) EXPECT_NEAR(s.eq.wheelLoads[w], ref.eq.wheelLoads[w], 2e-3 * ref.eq.wheelLoads[w]);
  EXPECT_NEAR(s.eq.chassisHeight, ref.eq.chassisHeight, 1e-3);
}

TEST(MotionRatio, EquivalentRearSpringGivesTheSameWheelRate) {
  // The paper topology moves the rear spring to the knuckle with k' = k (MR/MR')^2.
  auto ratioOf = [](const vehicle::Vehicle& v, const std::string& name) {
    for (const vehicle::MotionRatio& r : vehicle::motionRatios(v))
      if (r.element == name) return r.ratio;
    return 0.0;
  };
  const vehicle::Vehicle sedan = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/sedan.toml")));
  const vehicle::Vehicle paper = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/paper.toml")));
  auto stiffness = [](const vehicle::Vehicle& v, const std::string& name) {
    return v.model.springs[std::find_if(v.model.springs.begin(), v.model.springs.end(),
                                        [&](const mb::SpringDamper& s) { return s.name == name; }) -
                           v.model.springs.begin()]
        .spring.coefficient;
  };
  const double rateSedan = stiffness(sedan, "spring_RL") * std::pow(ratioOf(sedan, "spring_RL"), 2);
  const double ratePaper = stiffness(paper, "spring_RL") * std::pow(ratioOf(paper, "spring_RL"), 2);
  EXPECT_NEAR(ratePaper, rateSedan, 1e-4 * rateSedan);
  // The front is the same MacPherson in both: the same motion ratio.
  EXPECT_NEAR(ratioOf(paper, "strut_FL"), ratioOf(sedan, "strut_FL"), 1e-6);
}

TEST(VehicleFile, BadInputNamesFileLineKeyAndExpectation) {
  const std::string base = sedanText();
  // Negative mass.
  std::string e = loadError(replaced(base, "mass = 9.072", "mass = -9.072"));
  EXPECT_NE(e.find("test_bad_vehicle.toml:"), std::string::npos) << e;
  EXPECT_NE(e.find("mass"), std::string::npos) << e;
  EXPECT_NE(e.find("expected a mass in [0.001, 1e+06) kg, got -9.072"), std::string::npos) << e;
  // Missing key.
  e = loadError(replaced(base, "design_height = 0.5128", ""));
  EXPECT_NE(e.find("missing key 'vehicle.design_height'"), std::string::npos) << e;
  // Wrong type.
  e = loadError(replaced(base, "free_length = 0.355374", "free_length = \"long\""));
  EXPECT_NE(e.find("free_length"), std::string::npos) << e;
  EXPECT_NE(e.find("length"), std::string::npos) << e;
  // Wrong unit.
  e = loadError(replaced(base, "free_length = 0.355374", "free_length = \"355 kg\""));
  EXPECT_NE(e.find("'kg' is not a unit of length"), std::string::npos) << e;
  // Non-positive-definite inertia.
  e = loadError(replaced(base, "inertia = [1.0, 1.0, 1.0]", "inertia = [1.0, 1.0, 3.0]"));
  EXPECT_NE(e.find("triangle inequality"), std::string::npos) << e;
  // Unknown key (a typo).
  e = loadError(replaced(base, "stiffness = 369149.0", "stifness = 369149.0"));
  EXPECT_NE(e.find("unknown key 'springs[0].stifness'"), std::string::npos) << e;
  // A line number that points at the offending line.
  const std::string bad = replaced(base, "mass = 9.072", "mass = -9.072");
  const size_t lineOfBad = 1 + std::count(bad.begin(), bad.begin() + static_cast<long>(bad.find("mass = -9.072")), '\n');
  e = loadError(bad);
  EXPECT_NE(e.find(":" + std::to_string(lineOfBad) + ":"), std::string::npos) << e;
}

TEST(VehicleFile, ALinkThatCannotBeAssembledIsReported) {
  // A tie rod of 2 m cannot close the loop at any suspension position (one a
  // few centimetres off can: the knuckle just steers to take it up).
  const std::string text = replaced(sedanText(), "length = 0.382562", "length = 2.0");
  const std::string path = asset("vehicles/test_unassemblable.toml");
  {
    std::ofstream f(path);
    f << text;
  }
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(path));
  std::filesystem::remove(path);
  mb::MultibodyDae dae(v.model);
  integ::Vec q = vehicle::designPositions(v);
  std::string msg;
  EXPECT_FALSE(vehicle::assemble(v, dae, 0, q, msg));
  EXPECT_NE(msg.find("cannot close"), std::string::npos) << msg;
}
