// The planar rung in closed form (physics/vehicle/planar_car.h) against the
// multibody planar model it is written from (a second algorithm: the
// generic joint recursion with the rack as driver constraints): the same
// accelerations at the same state, the same motion over a J-turn; its
// analytic mass matrix against finite differences of its residual.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrator/bdf.h"
#include "closed_form_pair.h"
#include "multibody/model_error.h"
#include "terrain/terrain.h"
#include "vehicle/planar_car.h"
#include "vehicle/planar_model.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

struct Planar {
  vehicle::Vehicle linkage;
  vehicle::PlanarDerivation derivation;
  explicit Planar(const char* file)
      : linkage(vehicle::buildVehicle(vehicle::loadVehicleFile(asset(file)))), derivation(vehicle::derivePlanar(linkage)) {}
  const vehicle::Vehicle& vehicle() const { return derivation.vehicle; }
};

const Planar& sedan() {
  static const Planar p("vehicles/sedan.toml");
  return p;
}

// The sedan with a powertrain: the crank is one more coordinate.
const Planar& sedanDrive() {
  static const Planar p("vehicles/sedan_drive.toml");
  return p;
}

const Planar& vehicleNamed(const std::string& name) { return name == "sedan_drive" ? sedanDrive() : sedan(); }

using Pair = testing_closed_form::Pair<vehicle::PlanarCar>;
using testing_closed_form::accelerations;
using testing_closed_form::Accelerations;

// A state of the closed form: speeds, yaw rate, roll and pitch with their
// rates, wheel spins from a longitudinal slip.
struct State {
  double forward = 20, sideways = 0, yawRate = 0, roll = 0, pitch = 0, rollRate = 0, pitchRate = 0, slip = 0;
};

void makeState(const vehicle::Vehicle& v, const State& s, integ::Vec& q, integ::Vec& vel) {
  const int n = vehicle::PlanarCar::kCoordinates + (v.layout.engine >= 0 ? 1 : 0);
  q.setZero(n);
  vel.setZero(n);
  q(vehicle::PlanarCar::X) = 3.0;
  q(vehicle::PlanarCar::Y) = -2.0;
  q(vehicle::PlanarCar::Yaw) = 0.4;
  q(vehicle::PlanarCar::Roll) = s.roll;
  q(vehicle::PlanarCar::Pitch) = s.pitch;
  vel.head<5>() << s.forward, s.sideways, s.yawRate, s.rollRate, s.pitchRate;
  for (int w = 0; w < 4; ++w) {
    const double R = tyre::unloadedRadius(v.wheel(w).tyre) * 0.97;
    vel(vehicle::PlanarCar::Spin + w) = v.layout.wheels[w].spinSign * (1 + s.slip) * s.forward / R;
    q(vehicle::PlanarCar::Spin + w) = 0.3 * w;
  }
  if (n > vehicle::PlanarCar::kCoordinates) {  // the crank a little faster than the driven wheels in its gear
    const double wheels = v.layout.wheels[2].spinSign * vel(vehicle::PlanarCar::Spin + 2);
    vel(vehicle::PlanarCar::Engine) = 12.0 * wheels + 5.0;
    q(vehicle::PlanarCar::Engine) = 1.0;
  }
}

class PlanarCarOf : public ::testing::TestWithParam<const char*> {};

TEST_P(PlanarCarOf, SameAccelerationsAsTheMultibodyPlanarModel) {
  // The same equations: any difference is an error in one of them (rounding
  // and the multibody model's constrained solve aside).
  Pair p(vehicleNamed(GetParam()).vehicle());
  ASSERT_EQ(p.car.coordinates() + 3, p.v.model.nv);  // the rack and the steered carriers' rack travel
  struct Case {
    State state;
    double rack = 0, rackRate = 0, rackAccel = 0;
  };
  const std::vector<Case> cases = {
      {{}},                                                           // straight, free rolling
      {{20, 1.5, 0.3, 0.03, -0.01, 0.2, -0.1, 0.05}, 0.01},           // cornering, rolling, slipping
      {{15, 4.0, -0.6, -0.05, 0.02, -0.5, 0.3, -0.3}, -0.02},         // sliding: saturated tyres
      {{10, 0.5, 0.2, 0.2, 0.0, 0.0, 0.0, 0.0}},                      // rolled far: a wheel in the air
      {{20, 0.5, 0.25, 0.01, 0.0, 0.0, 0.0, 0.0}, 0.01, 0.05, 2.0},   // steering: the rack moving
  };
  // A moving rack's share goes through the derivatives of tables of the
  // moved bodies' first moment and momentum (the closed form's) against
  // those of the carriers' poses (the multibody model's): splines through
  // the same values, whose derivatives differ by their interpolation error.
  testing_closed_form::expectSameAccelerations(p, cases, makeState, [](const Case& c) {
    return c.rackRate != 0 || c.rackAccel != 0 ? 1e-6 : 1e-7;
  });
}

// A J-turn at 80 km/h on both models (BDF2, 2 Newton iterations): RMS
// differences of yaw rate and roll as % of their peaks.
struct Turn {
  double peakYaw = 0, yawPct = 0, rollPct = 0;
};

Turn turnBoth(bool kinked, double h) {
  Pair p(sedan().vehicle());
  p.rack.travel = 0.012;  // about 0.4 of the tyres' limit at this speed
  p.rack.start = 0.5;
  p.rack.kinked = kinked;
  integ::BdfOptions o;
  integ::BdfIntegrator closed(p.car, o), multibody(p.dae, o);
  integ::Vec q, v, qm, vm;
  makeState(p.v, {22.2, 0, 0, 0, 0, 0, 0, 0}, q, v);
  for (int w = 0; w < 4; ++w) v(vehicle::PlanarCar::Spin + w) /= 1.0 / 0.97;  // rolling at the loaded radius, about
  p.car.toMultibody(0, q, v, qm, vm);
  integ::Message msg;
  EXPECT_EQ(closed.initialize(0, q, v, msg), integ::EvalStatus::Ok) << msg.c_str();
  EXPECT_EQ(multibody.initialize(0, qm, vm, msg), integ::EvalStatus::Ok) << msg.c_str();
  double peakRoll = 0, yawSq = 0, rollSq = 0;
  Turn out;
  int n = 0;
  while (closed.current().t < 4.0 - 1e-9) {
    if (!closed.step(h).ok() || !multibody.step(h).ok()) {
      ADD_FAILURE() << "a step failed at t = " << closed.current().t;
      return out;
    }
    integ::Vec qc, vc;
    p.car.fromMultibody(multibody.current().q, multibody.current().v, qc, vc);
    const double yaw = closed.current().v(vehicle::PlanarCar::Yaw), roll = closed.current().q(vehicle::PlanarCar::Roll);
    out.peakYaw = std::max(out.peakYaw, std::abs(vc(vehicle::PlanarCar::Yaw)));
    peakRoll = std::max(peakRoll, std::abs(qc(vehicle::PlanarCar::Roll)));
    yawSq += std::pow(yaw - vc(vehicle::PlanarCar::Yaw), 2);
    rollSq += std::pow(roll - qc(vehicle::PlanarCar::Roll), 2);
    ++n;
  }
  out.yawPct = 100 * std::sqrt(yawSq / n) / out.peakYaw;
  out.rollPct = 100 * std::sqrt(rollSq / n) / peakRoll;
  std::printf("J-turn (%s steering, %g ms): peak yaw rate %.3f rad/s; closed form against the multibody model: RMS "
              "%.4f %% (yaw rate), %.4f %% (roll) of peak\n",
              kinked ? "kinked" : "smooth", 1e3 * h, out.peakYaw, out.yawPct, out.rollPct);
  return out;
}

TEST(PlanarCar, TurnsAsTheMultibodyPlanarModel) {
  // Smooth steering: the same equations integrated alike; the difference is
  // the rounding, the Newton iterations' and the steering's acceleration,
  // which the closed form takes over the step (its rate's change).
  const Turn smooth = turnBoth(false, 0.01);
  EXPECT_GT(smooth.peakYaw, 0.2);
  EXPECT_LT(smooth.yawPct, 0.005);
  EXPECT_LT(smooth.rollPct, 0.005);
  // A ramp: the rate jumps, an impulse of the steering's acceleration that
  // the closed form takes over the step and the multibody form through its
  // driven coordinates. A step apart at 10 ms, the same at 1 ms.
  const Turn kinked = turnBoth(true, 0.001);
  EXPECT_LT(kinked.yawPct, 0.005);
  EXPECT_LT(kinked.rollPct, 0.005);
}

TEST_P(PlanarCarOf, MassMatrixIsTheResidualsDerivative) {
  Pair p(vehicleNamed(GetParam()).vehicle());
  integ::Vec q, v;
  makeState(p.v, {18, 1.0, 0.4, 0.04, -0.02, 0.3, 0.1, 0.1}, q, v);
  p.rack.travel = 0.01;
  testing_closed_form::expectMassMatrixIsTheResidualsDerivative(p.car, 0.5, q, v);
}

TEST_P(PlanarCarOf, CoordinatesMapToTheMultibodyModelAndBack) {
  Pair p(vehicleNamed(GetParam()).vehicle());
  p.rack.travel = -0.02;
  integ::Vec q, v, qm, vm, q2, v2;
  makeState(p.v, {12, 0.7, -0.2, 0.01, 0.02, 0.1, 0.2, 0.0}, q, v);
  p.car.toMultibody(1.0, q, v, qm, vm);
  ASSERT_EQ(qm.size(), p.v.model.nq);
  p.car.fromMultibody(qm, vm, q2, v2);
  EXPECT_EQ(q, q2);
  EXPECT_EQ(v, v2);
  for (const mb::CutJoint& c : p.v.model.cutJoints) EXPECT_EQ(qm(p.v.model.bodies[c.drivenBody].qIndex), -0.02);
}

TEST_P(PlanarCarOf, SpinColumnsFromTheForceLawsAreTheResiduals) {
  // Cornering, and rolled far (a wheel in the air).
  Pair p(vehicleNamed(GetParam()).vehicle());
  testing_closed_form::expectSpinColumnsFromTheForceLaws(p, std::vector<State>{State{20, 1.5, 0.3, 0.03, -0.01, 0.2, -0.1, 0.05},
                                                     State{10, 0.5, 0.2, 0.2, 0.0, 0.0, 0.0, 0.0}}, makeState);
}

TEST_P(PlanarCarOf, StateJacobianIsTheResidualsDerivative) {
  // The accelerations' cases (straight; cornering with the brakes on;
  // sliding, saturated; rolled far, a wheel in the air) and a slow one (the
  // transient slips blended in) with the rack moving; the drive on the rear
  // wheels and, where the car has one, its clutch slipping.
  Pair p(vehicleNamed(GetParam()).vehicle());
  const std::vector<std::pair<State, double>> cases = {
      {{}, 0.0},
      {{20, 1.5, 0.3, 0.03, -0.01, 0.2, -0.1, 0.05}, 0.01},
      {{15, 4.0, -0.6, -0.05, 0.02, -0.5, 0.3, -0.3}, -0.02},
      {{10, 0.5, 0.2, 0.2, 0.0, 0.0, 0.0, 0.0}, 0.0},
      {{1.2, 0.2, 0.1, 0.01, 0.0, 0.0, 0.0, 0.1}, 0.01},
  };
  // Central differences of a ~1e4 N residual with increments of 1e-6:
  // ~1e-10 of a column from rounding, and the truncation of a tyre's
  // curvature: 1e-6 leaves room for both and none for a missing term.
  testing_closed_form::expectStateJacobians(p, cases, makeState, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Vehicles, PlanarCarOf, ::testing::Values("sedan", "sedan_drive"));

TEST(PlanarCar, RefusesWhatIsNotAPlanarModel) {
  const terrain::PlaneTerrain ground;
  EXPECT_THROW(vehicle::PlanarCar(sedan().linkage, ground), mb::ModelError);
}

}  // namespace
}  // namespace bdfcar
