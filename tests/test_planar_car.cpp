// The planar rung in closed form (physics/vehicle/planar_car.h) against the
// multibody planar model it is written from (a second algorithm: the
// generic joint recursion with the rack as driver constraints): the same
// accelerations at the same state, the same motion over a J-turn; its
// analytic mass matrix against finite differences of its residual.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrator/bdf.h"
#include "integrator/forward_dynamics.h"
#include "multibody/model_error.h"
#include "terrain/terrain.h"
#include "vehicle/planar_car.h"
#include "vehicle/planar_model.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

// The rack held, or moved smoothly to a travel over a second (a J-turn's steering).
struct Rack final : mb::TimeSignal {
  double travel = 0, start = -1;  // start < 0: held at travel
  double rate = 0, accel = 0;
  bool kinked = false;  // a ramp: the rate jumps at its ends
  mb::SignalValue at(double t) const override {
    if (start < 0) return {travel, rate, accel};
    if (kinked) {
      const double s = std::clamp(t - start, 0.0, 1.0);
      return {travel * s, s > 0 && s < 1 ? travel : 0.0, 0.0};
    }
    // A smooth step over a second (C2: 10 s^3 - 15 s^4 + 6 s^5).
    const double s = std::clamp(t - start, 0.0, 1.0), s2 = s * s;
    return {travel * s2 * s * (10 - 15 * s + 6 * s2), travel * 30 * s2 * (1 - 2 * s + s2), travel * 60 * s * (1 - 3 * s + 2 * s2)};
  }
};

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

// Both models of one vehicle on level ground, with the same inputs.
struct Pair {
  const vehicle::Vehicle& v;
  terrain::PlaneTerrain ground;
  Rack rack;
  vehicle::PlanarCar car;
  mb::MultibodyDae dae;
  vehicle::VehicleForces forces;
  explicit Pair(const vehicle::Vehicle& planar) : v(planar), car(planar, ground), dae(planar.model), forces(planar, ground) {
    car.setRack(&rack);
    dae.addForceProvider(&forces);
    for (int slot = 0; slot < planar.model.nDrivers; ++slot) dae.setDriverSignal(slot, &rack);
  }
  void inputs(int w, double drive, double brake) {
    car.forces().setDriveTorque(w, drive);
    car.forces().setBrakeCapacity(w, brake);
    forces.setDriveTorque(w, drive);
    forces.setBrakeCapacity(w, brake);
    // A powertrain's: part throttle in a low gear, the clutch slipping.
    const vehicle::DrivelineCommand c{0.6, 250.0, 12.0};
    car.forces().setDriveline(c);
    forces.setDriveline(c);
  }
};

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

// Accelerations of both models at one state (the multibody model's mapped
// onto the closed form's coordinates), and what the tyres did there.
struct Accelerations {
  integ::Vec closed, multibody;
  int wheelsInContact = 0;
  double largestFriction = 0;  // |F_horizontal| / Fz of the most used tyre
};

Accelerations accelerations(Pair& p, double t, const integ::Vec& q, const integ::Vec& v) {
  integ::Counters counters;
  integ::Message msg;
  Accelerations out;
  // At an accepted point (no step under way: the rack's acceleration is the
  // signal's, the brakes' springs as they were accepted), the contact planes cast.
  p.car.beginStep(t, q, v);
  p.car.forces().markAccepted(t);
  integ::ForwardDynamics closed(p.car);
  integ::Vec lambda;
  EXPECT_EQ(closed.solve(t, q, v, 0, 0, out.closed, lambda, counters, msg), integ::EvalStatus::Ok) << msg.c_str();
  integ::Vec qm, vm, am;
  p.car.toMultibody(t, q, v, qm, vm);
  p.dae.beginStep(t, qm, vm);
  p.forces.markAccepted(t);
  integ::ForwardDynamics multibody(p.dae);
  EXPECT_EQ(multibody.solve(t, qm, vm, 0, 0, am, lambda, counters, msg), integ::EvalStatus::Ok) << msg.c_str();
  integ::Vec unused;
  p.car.fromMultibody(qm, am, unused, out.multibody);
  for (const vehicle::WheelOutput& o : p.car.forces().outputs()) {
    if (!o.out.inContact) continue;
    ++out.wheelsInContact;
    out.largestFriction = std::max(out.largestFriction, std::hypot(o.out.Fx, o.out.Fy) / o.out.Fz);
  }
  return out;
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
  bool sawSaturated = false, sawAirborne = false;
  for (size_t i = 0; i < cases.size(); ++i) {
    for (int w = 0; w < 4; ++w) p.inputs(w, w >= 2 ? 300.0 : 0.0, i == 1 ? 800.0 : 0.0);
    p.rack.travel = cases[i].rack;
    p.rack.rate = cases[i].rackRate;
    p.rack.accel = cases[i].rackAccel;
    integ::Vec q, v;
    makeState(p.v, cases[i].state, q, v);
    const Accelerations a = accelerations(p, 0.5, q, v);
    const double peak = tyre::peakFriction(p.v.wheel(0).tyre, 1.0);
    const double worst =
        (a.closed - a.multibody).cwiseAbs().cwiseQuotient((1 + a.multibody.cwiseAbs().array()).matrix()).maxCoeff();
    std::printf("case %zu: %d wheels in contact, most used tyre at %.2f of its peak friction; largest difference "
                "%.2g of the acceleration\n",
                i, a.wheelsInContact, a.largestFriction / peak, worst);
    sawSaturated = sawSaturated || a.largestFriction > 0.95 * peak;
    sawAirborne = sawAirborne || a.wheelsInContact < 4;
    // A moving rack's share goes through the derivatives of tables of the
    // moved bodies' first moment and momentum (the closed form's) against
    // those of the carriers' poses (the multibody model's): splines through
    // the same values, whose derivatives differ by their interpolation error.
    const double tolerance = cases[i].rackRate != 0 || cases[i].rackAccel != 0 ? 1e-6 : 1e-7;
    for (int k = 0; k < p.car.coordinates(); ++k)
      EXPECT_NEAR(a.closed(k), a.multibody(k), tolerance * (1 + std::abs(a.multibody(k)))) << "case " << i << ", coordinate " << k;
  }
  EXPECT_TRUE(sawSaturated);
  EXPECT_TRUE(sawAirborne);
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
  p.car.beginStep(0.5, q, v);
  integ::Mat M;
  ASSERT_TRUE(p.car.massMatrix(0.5, q, M));
  integ::Residual r0, r1;
  integ::DaeSizes n = p.car.sizes();
  r0.resize(n);
  r1.resize(n);
  integ::Message msg;
  const integ::Vec a = integ::Vec::LinSpaced(n.nv, -2, 3), lambda;
  ASSERT_EQ(p.car.residual(0.5, q, v, a, lambda, r0, true, msg), integ::EvalStatus::Ok);
  for (int k = 0; k < n.nv; ++k) {
    integ::Vec ak = a;
    ak(k) += 1.0;  // the residual is linear in a: a unit difference is exact up to rounding
    ASSERT_EQ(p.car.residual(0.5, q, v, ak, lambda, r1, true, msg), integ::EvalStatus::Ok);
    for (int j = 0; j < n.nv; ++j) EXPECT_NEAR(r1.F(j) - r0.F(j), M(j, k), 1e-8 * (1 + M.norm())) << j << ", " << k;
  }
  EXPECT_NEAR((M - M.transpose()).norm(), 0.0, 1e-12 * M.norm());
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

INSTANTIATE_TEST_SUITE_P(Vehicles, PlanarCarOf, ::testing::Values("sedan", "sedan_drive"));

TEST(PlanarCar, RefusesWhatIsNotAPlanarModel) {
  const terrain::PlaneTerrain ground;
  EXPECT_THROW(vehicle::PlanarCar(sedan().linkage, ground), mb::ModelError);
}

}  // namespace
}  // namespace bdfcar
