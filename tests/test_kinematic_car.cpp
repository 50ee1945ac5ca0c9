// The kinematic rung in closed form (physics/vehicle/kinematic_car.h)
// against the multibody kinematic model it is written from (a second
// algorithm: the generic joint recursion over the same tables, with the
// rack as driver constraints): the same accelerations at the same state,
// the same motion over a J-turn; its analytic mass matrix against
// differences of its residual.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "integrator/bdf.h"
#include "closed_form_pair.h"
#include "multibody/model_error.h"
#include "terrain/bullet/bullet_terrain.h"
#include "terrain/terrain.h"
#include "terrain/terrain_file.h"
#include "vehicle/equilibrium.h"
#include "vehicle/kinematic_car.h"
#include "vehicle/kinematic_model.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar {
namespace {

using vehicle::KinematicCar;

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

// The wheels made exactly symmetric about their spin axes: the closed form
// takes the mean of a wheel's transverse moments (closed_form_car.h), the
// multibody model the moments as written (the sedan's differ by 6e-6 of
// them), so the same equations need the same wheels.
vehicle::VehicleSpec symmetricWheels(vehicle::VehicleSpec spec) {
  for (const vehicle::WheelSpec& w : spec.wheels)
    for (vehicle::BodySpec& b : spec.bodies) {
      if (b.name != w.spindle) continue;
      const Eigen::Vector3d a = b.joint.axis.normalized();
      const double J = a.dot(b.inertia * a), transverse = 0.5 * (b.inertia.trace() - J);
      b.inertia = transverse * (Eigen::Matrix3d::Identity() - a * a.transpose()) + J * a * a.transpose();
    }
  return spec;
}

struct Kinematic {
  vehicle::Vehicle linkage;
  vehicle::KinematicDerivation derivation;
  Kinematic(const char* file, bool symmetric)
      : linkage(vehicle::buildVehicle(symmetric ? symmetricWheels(vehicle::loadVehicleFile(asset(file)))
                                                : vehicle::loadVehicleFile(asset(file)))),
        derivation(vehicle::deriveKinematic(linkage)) {}
  const vehicle::Vehicle& vehicle() const { return derivation.vehicle; }
};

// "sedan", "sedan_drive" (a powertrain: the crank is one more coordinate),
// "paper", with symmetric wheels; "sedan as drawn".
const Kinematic& vehicleNamed(const std::string& name) {
  static const Kinematic sedan("vehicles/sedan.toml", true), drawn("vehicles/sedan.toml", false);
  static const Kinematic drive("vehicles/sedan_drive.toml", true);
  static const Kinematic paper("vehicles/paper.toml", true);
  return name == "sedan_drive" ? drive : name == "paper" ? paper : name == "sedan as drawn" ? drawn : sedan;
}

using Pair = testing_closed_form::Pair<KinematicCar>;
using testing_closed_form::accelerations;
using testing_closed_form::Accelerations;

// A state of the closed form: the chassis' speeds, attitude and rates, its
// height against design, the travels and their rates, wheel spins from a
// longitudinal slip.
struct State {
  double forward = 20, sideways = 0, yawRate = 0, roll = 0, pitch = 0, rollRate = 0, pitchRate = 0;
  double sink = 0.02, heaveRate = 0, travel = 0, travelRate = 0, slip = 0;
};

void makeState(const vehicle::Vehicle& v, const State& s, integ::Vec& q, integ::Vec& vel) {
  const int n = KinematicCar::kCoordinates + (v.layout.engine >= 0 ? 1 : 0);
  q.setZero(n + 1);
  vel.setZero(n);
  const Eigen::Quaterniond att = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(s.pitch, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(s.roll, Eigen::Vector3d::UnitX());
  q.head<3>() << 3.0, -2.0, v.spec.designHeight - s.sink;
  q.segment<4>(3) << att.w(), att.x(), att.y(), att.z();
  vel.head<6>() << s.forward, s.sideways, s.heaveRate, s.rollRate, s.pitchRate, s.yawRate;
  for (int w = 0; w < 4; ++w) {
    const double R = tyre::unloadedRadius(v.wheel(w).tyre) * 0.97;
    q(KinematicCar::TravelQ + w) = s.travel * (w % 2 ? 1.0 : -0.5) + 0.003 * w;
    vel(KinematicCar::TravelV + w) = s.travelRate * (w < 2 ? 1.0 : -0.7);
    vel(KinematicCar::SpinV + w) = v.layout.wheels[w].spinSign * (1 + s.slip) * s.forward / R;
    q(KinematicCar::SpinQ + w) = 0.3 * w;
  }
  if (n > KinematicCar::kCoordinates) {  // the crank a little faster than the driven wheels in its gear
    const double wheels = v.layout.wheels[2].spinSign * vel(KinematicCar::SpinV + 2);
    vel(KinematicCar::EngineV) = 12.0 * wheels + 5.0;
    q(KinematicCar::EngineQ) = 1.0;
  }
}

class KinematicCarOf : public ::testing::TestWithParam<const char*> {};

TEST_P(KinematicCarOf, SameAccelerationsAsTheMultibodyKinematicModel) {
  // The same equations: any difference is an error in one of them (rounding
  // and the multibody model's constrained solve aside).
  Pair p(vehicleNamed(GetParam()).vehicle());
  ASSERT_EQ(p.car.coordinates() + p.v.model.nDrivers, p.v.model.nv);  // the rack and the steered tables' rack travel
  struct Case {
    State state;
    double rack = 0, rackRate = 0, rackAccel = 0;
  };
  const std::vector<Case> cases = {
      {{}},                                                                          // straight, free rolling
      {{20, 1.5, 0.3, 0.03, -0.01, 0.2, -0.1, 0.025, 0.1, 0.02, 0.3, 0.05}, 0.01},  // cornering, rolling, slipping, travelling
      {{15, 4.0, -0.6, -0.05, 0.02, -0.5, 0.3, 0.03, -0.2, -0.03, -0.5, -0.3}, -0.02},  // sliding: saturated tyres
      {{10, 0.5, 0.2, 0.12, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}},               // rolled and high: a wheel in the air
      {{20, 0.5, 0.25, 0.01, 0.0, 0.0, 0.0, 0.02, 0.0, 0.01, 0.1, 0.0}, 0.01, 0.05, 2.0},  // steering: the rack moving
  };
  // As drawn, the wheels' transverse moments differ by 6e-6 of them, a
  // few 1e-8 of the car's rotational inertia: that much apart.
  const double tolerance = std::string(GetParam()) == "sedan as drawn" ? 1e-6 : 1e-7;
  testing_closed_form::expectSameAccelerations(p, cases, makeState, [&](const Case&) { return tolerance; });
}

TEST_P(KinematicCarOf, MassMatrixIsTheResidualsDerivative) {
  Pair p(vehicleNamed(GetParam()).vehicle());
  integ::Vec q, v;
  makeState(p.v, {18, 1.0, 0.4, 0.04, -0.02, 0.3, 0.1, 0.02, 0.1, 0.02, 0.2, 0.1}, q, v);
  p.rack.travel = 0.01;
  testing_closed_form::expectMassMatrixIsTheResidualsDerivative(p.car, 0.5, q, v);
}

TEST_P(KinematicCarOf, CoordinatesMapToTheMultibodyModelAndBack) {
  Pair p(vehicleNamed(GetParam()).vehicle());
  p.rack.travel = -0.02;
  integ::Vec q, v, qm, vm, q2, v2;
  makeState(p.v, {12, 0.7, -0.2, 0.01, 0.02, 0.1, 0.2, 0.01, 0.05, 0.02, 0.1, 0.0}, q, v);
  p.car.toMultibody(1.0, q, v, qm, vm);
  ASSERT_EQ(qm.size(), p.v.model.nq);
  p.car.fromMultibody(qm, vm, q2, v2);
  EXPECT_EQ(q, q2);
  EXPECT_EQ(v, v2);
  for (const mb::CutJoint& c : p.v.model.cutJoints)
    EXPECT_EQ(qm(p.v.model.bodies[c.drivenBody].qIndex + c.drivenCoordinate), -0.02);
}

TEST_P(KinematicCarOf, SpinColumnsFromTheForceLawsAreTheResiduals) {
  // Cornering, and rolled far (a wheel in the air).
  Pair p(vehicleNamed(GetParam()).vehicle());
  testing_closed_form::expectSpinColumnsFromTheForceLaws(p, std::vector<State>{State{20, 1.5, 0.3, 0.03, -0.01, 0.2, -0.1, 0.025, 0.1, 0.02, 0.3, 0.05},
                                                     State{10, 0.5, 0.2, 0.12, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}}, makeState);
}

// The accelerations' cases (straight; cornering, travelling, with the
// brakes on; sliding, saturated; rolled and high, a wheel in the air) and a
// slow one (the transient slips blended in) with the rack moving; the drive
// on the rear wheels and, where the car has one, its clutch slipping.
// Central differences of a ~1e4 N residual with increments of 1e-6: ~1e-10
// of a column from rounding, and the truncation of a tyre's curvature: 1e-6
// leaves room for both and none for a missing term.
// Straight running has a little slip, sideways and along: the Magic
// Formula takes signs of its slips (the equivalent slip angle's, the
// curvature factor's), kinks at zero slip that differences across would not
// differentiate; a little roll too: the textbook evaluation takes the
// camber's magnitude. predictedAhead: the ground cast that far behind the state
// (stateJacobianError).
void expectStateJacobianIsTheResidualsDerivative(Pair& p, double x, double predictedAhead = 0.0) {
  const std::vector<std::pair<State, double>> cases = {
      {{20, 0.05, 0, 0.01, 0, 0, 0, 0.02, 0, 0, 0, 0.01}, 0.0},
      {{20, 1.5, 0.3, 0.03, -0.01, 0.2, -0.1, 0.025, 0.1, 0.02, 0.3, 0.05}, 0.01},
      {{15, 4.0, -0.6, -0.05, 0.02, -0.5, 0.3, 0.03, -0.2, -0.03, -0.5, -0.3}, -0.02},
      {{10, 0.5, 0.2, 0.12, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, 0.0},
      {{1.2, 0.2, 0.1, 0.01, 0.0, 0.0, 0.0, 0.02, 0.0, 0.01, 0.1, 0.1}, 0.01},
      {{12, 7.0, 1.0, 0.04, 0.01, 0.3, 0.0, 0.03, 0.0, 0.0, 0.0, 0.5}, 0.02},  // sliding further (the Magic Formula's peak lies further out)
  };
  testing_closed_form::expectStateJacobians(p, cases, makeState, 1e-6, x, predictedAhead);
}

TEST_P(KinematicCarOf, StateJacobianIsTheResidualsDerivative) {
  Pair p(vehicleNamed(GetParam()).vehicle());
  expectStateJacobianIsTheResidualsDerivative(p, 3.0);
}

TEST(KinematicCar, StateJacobianOfMagicFormulaTyresIsTheResidualsDerivative) {
  // PAC2002 as Chrono 9 evaluates it and as the textbook does (camber, the
  // combined-slip weighting functions, the rolling radius).
  for (const char* file : {"vehicles/sedan_pac2002_chrono9.toml", "vehicles/sedan_pac2002.toml"}) {
    const Kinematic k(file, true);
    Pair p(k.vehicle());
    expectStateJacobianIsTheResidualsDerivative(p, 3.0);
  }
}

TEST(KinematicCar, StateJacobianOnRoughGroundUnderEnvelopingTyresIsTheResidualsDerivative) {
  // The cams ride on the rough road's profile at the wheel in every
  // residual (the road inside the step): the contact plane's derivative in
  // the wheel's position is part of F_q.
  const Kinematic k("vehicles/sedan_envelope.toml", true);
  const std::unique_ptr<terrain::Terrain> rough = terrain::makeTerrain(terrain::loadTerrain(asset("terrain/rough.toml")));
  Pair p(k.vehicle(), rough.get());
  expectStateJacobianIsTheResidualsDerivative(p, 60.0, 0.0123);
}

INSTANTIATE_TEST_SUITE_P(Vehicles, KinematicCarOf, ::testing::Values("sedan", "sedan_drive", "paper", "sedan as drawn"),
                         [](const ::testing::TestParamInfo<const char*>& i) {
                           std::string n = i.param;
                           std::replace(n.begin(), n.end(), ' ', '_');
                           return n;
                         });

// A J-turn at 80 km/h on both models from their static equilibrium (BDF2,
// 2 Newton iterations, 10 ms): RMS differences of yaw rate and roll rate as
// % of their peaks.
TEST(KinematicCar, TurnsAsTheMultibodyKinematicModel) {
  Pair p(vehicleNamed("sedan").vehicle());
  integ::Vec qm = vehicle::designPositions(p.v), lambda = integ::Vec::Zero(p.v.model.nc);
  const vehicle::EquilibriumReport rest = vehicle::settleStatic(p.v, p.dae, p.forces, 0.0, qm, lambda);
  ASSERT_TRUE(rest.converged) << rest.message;
  integ::Vec q, v, vm = integ::Vec::Zero(p.v.model.nv);
  p.car.fromMultibody(qm, vm, q, v);
  v(0) = 22.2;
  for (int w = 0; w < 4; ++w)
    v(KinematicCar::SpinV + w) = p.v.layout.wheels[w].spinSign * 22.2 / (0.97 * tyre::unloadedRadius(p.v.wheel(w).tyre));
  p.car.toMultibody(0, q, v, qm, vm);
  p.forces.reset(0);
  p.rack.travel = 0.012;  // about 0.4 of the tyres' limit at this speed
  p.rack.start = 0.5;
  integ::BdfOptions o;
  integ::BdfIntegrator closed(p.car, o), multibody(p.dae, o);
  integ::Message msg;
  ASSERT_EQ(closed.initialize(0, q, v, msg), integ::EvalStatus::Ok) << msg.c_str();
  ASSERT_EQ(multibody.initialize(0, qm, vm, msg), integ::EvalStatus::Ok) << msg.c_str();
  double peakYaw = 0, peakRoll = 0, yawSq = 0, rollSq = 0;
  int n = 0;
  while (closed.current().t < 4.0 - 1e-9) {
    ASSERT_TRUE(closed.step(0.01).ok() && multibody.step(0.01).ok()) << "a step failed at t = " << closed.current().t;
    integ::Vec qc, vc;
    p.car.fromMultibody(multibody.current().q, multibody.current().v, qc, vc);
    const integ::Vec& vk = closed.current().v;
    peakYaw = std::max(peakYaw, std::abs(vc(5)));
    peakRoll = std::max(peakRoll, std::abs(vc(3)));
    yawSq += std::pow(vk(5) - vc(5), 2);
    rollSq += std::pow(vk(3) - vc(3), 2);
    ++n;
  }
  const double yawPct = 100 * std::sqrt(yawSq / n) / peakYaw, rollPct = 100 * std::sqrt(rollSq / n) / peakRoll;
  std::printf("J-turn (10 ms): peak yaw rate %.3f rad/s; closed form against the multibody model: RMS %.4f %% (yaw "
              "rate), %.4f %% (roll rate) of peak\n",
              peakYaw, yawPct, rollPct);
  EXPECT_GT(peakYaw, 0.2);
  EXPECT_LT(yawPct, 0.01);
  EXPECT_LT(rollPct, 0.05);
}

TEST(KinematicCar, RefusesWhatIsNotAKinematicModel) {
  const terrain::PlaneTerrain ground;
  EXPECT_THROW(KinematicCar(vehicleNamed("sedan").linkage, ground), mb::ModelError);
}

TEST(KinematicCar, RefusesAWheelFarFromSymmetric) {
  // A wheel whose transverse moments differ by a tenth: its spin angle
  // matters, which the closed form does not carry.
  vehicle::VehicleSpec spec = vehicle::loadVehicleFile(asset("vehicles/sedan.toml"));
  for (vehicle::BodySpec& b : spec.bodies)
    if (b.name == spec.wheels[0].spindle) b.inertia(0, 0) *= 1.1;
  const vehicle::Vehicle linkage = vehicle::buildVehicle(spec);
  const terrain::PlaneTerrain ground;
  EXPECT_THROW(KinematicCar(vehicle::deriveKinematic(linkage).vehicle, ground), mb::ModelError);
}

}  // namespace
}  // namespace bdfcar
