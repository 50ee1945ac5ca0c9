// The wheel spins' Jacobian columns from the force laws alone
// (VehicleForces::addFastColumnParts, what the BDF integrator's fast-column
// refresh uses in place of a residual per column) against the second
// algorithm they replace: finite differences of the whole residual. The
// columns' rest (inertia, springs, everything but the tyres and brakes) is
// the same finite difference of the residual without the force laws, so
// whole = rest + parts must hold on every state: tyres in their linear
// range, saturated (a locked wheel, a spinning one), braking, in the air,
// and a powertrain's slipping clutch and differential.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "multibody/multibody_dae.h"
#include "terrain/terrain.h"
#include "tyre/tyre_model.h"
#include "test_files.h"
#include "vehicle/equilibrium.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_file.h"
#include "vehicle/vehicle_forces.h"

using namespace bdfcar;
using integ::Mat;
using integ::Vec;

namespace {

// The columns of F_v for the wheel spins by forward differences of dae's residual.
Mat spinColumnsByDifferences(mb::MultibodyDae& dae, double t, const Vec& q, const Vec& v, const Vec& lambda) {
  const int nv = static_cast<int>(v.size());
  const Vec a = Vec::Zero(nv);
  integ::Residual r0, r1;
  r0.resize(dae.sizes());
  r1.resize(dae.sizes());
  integ::Message msg;
  EXPECT_EQ(dae.residual(t, q, v, a, lambda, r0, false, msg), integ::EvalStatus::Ok) << msg.c_str();
  const std::vector<int>& spins = dae.fastColumns();
  Mat cols(nv, static_cast<int>(spins.size()));
  for (int k = 0; k < cols.cols(); ++k) {
    Vec vk = v;
    const double h = 1.5e-8 * std::max(1.0, std::abs(v(spins[k])));
    vk(spins[k]) += h;
    EXPECT_EQ(dae.residual(t, q, vk, a, lambda, r1, false, msg), integ::EvalStatus::Ok) << msg.c_str();
    cols.col(k) = (r1.F - r0.F) / h;
  }
  return cols;
}

struct SpinCase {
  double lift;                    // m, the chassis raised from its static pose (wheels in the air)
  std::array<double, 4> rolling;  // each wheel's spin as a multiple of free rolling at the chassis' speed
  bool brakes;                    // brakes on (their spring in its linear range, and saturated)
};

// |whole - rest - parts| over the tyres' and brakes' share, per case.
double partsError(const std::string& file, const SpinCase& c) {
  const vehicle::Vehicle veh = vehicle::buildVehicle(vehicle::loadVehicleFile(test::asset(file)));
  const mb::Model& m = veh.model;
  terrain::PlaneTerrain ground;
  vehicle::VehicleForces forces(veh, ground);
  mb::MultibodyDae whole(m), rest(m);
  whole.addForceProvider(&forces);
  std::vector<int> spins;
  for (const vehicle::WheelLayout& w : veh.layout.wheels) spins.push_back(w.spinV);
  whole.setFastColumns(spins);
  rest.setFastColumns(spins);
  EXPECT_TRUE(whole.hasFastColumnParts());
  EXPECT_FALSE(rest.hasFastColumnParts());

  Vec q = vehicle::designPositions(veh);
  std::string msg;
  EXPECT_TRUE(vehicle::assemble(veh, whole, 0, q, msg)) << msg;
  Vec lambda = Vec::Zero(m.nc);
  vehicle::settleStatic(veh, whole, forces, 0, q, lambda);
  const mb::Body& chassis = m.bodies[veh.layout.chassis];
  q(chassis.qIndex + 2) += c.lift;
  // 20 m/s along the chassis' x, the wheels turning at their multiples of rolling.
  const double speed = 20.0, t = 0.01;
  Vec v = Vec::Zero(m.nv);
  v(chassis.vIndex) = speed;
  for (int w = 0; w < 4; ++w) {
    const vehicle::WheelLayout& wl = veh.layout.wheels[w];
    v(wl.spinV) = c.rolling[w] * wl.spinSign * speed / tyre::Tyre(veh.wheel(w).tyre).unloadedRadius();
    if (c.brakes) forces.setBrakeCapacity(w, 800.0 + 300.0 * w);
  }
  whole.beginStep(t, q, v);
  if (veh.spec.powertrain) {
    // In gear, the crank 0.5 rad/s faster than the gearbox's input and the
    // clutch's capacity well above its torque there (its smooth range): the
    // driven spins move the clutch's torque on the crank and the drive
    // torques.
    const double ratio = 12.0;
    forces.setDriveline({0.4, 1.0e4, ratio});
    integ::Residual r;
    r.resize(whole.sizes());
    integ::Message m1;
    EXPECT_EQ(whole.residual(t, q, v, Vec::Zero(m.nv), lambda, r, false, m1), integ::EvalStatus::Ok);
    v(veh.layout.engineV) += ratio * forces.driveline().outputSpeed + 0.5 - forces.driveline().engineSpeed;
  }

  const Mat all = spinColumnsByDifferences(whole, t, q, v, lambda);
  const Mat inertial = spinColumnsByDifferences(rest, t, q, v, lambda);
  // The parts at the state of the last residual: evaluate it there again.
  integ::Residual r;
  r.resize(whole.sizes());
  integ::Message m2;
  EXPECT_EQ(whole.residual(t, q, v, Vec::Zero(m.nv), lambda, r, false, m2), integ::EvalStatus::Ok);
  Mat parts;
  whole.fastColumnParts(t, parts);
  const Mat share = all - inertial;
  EXPECT_GT(share.cwiseAbs().maxCoeff(), 100.0) << "the force laws give the columns nothing: the case tests nothing";
  // The force laws' change of each spin's own row over a finite move of
  // that spin, through saturation (3 rad/s: 4.5 % of slip at 20 m/s;
  // MultibodyDae::fastRowChange), against the whole residual's change of
  // that row less the residual's without the force laws.
  double rowError = 0;
  for (int k = 0; k < static_cast<int>(spins.size()); ++k) {
    const int i = spins[k];
    const double dv = 3.0;
    Vec vk = v;
    vk(i) += dv;
    integ::Residual w0, w1, r0, r1;
    for (integ::Residual* x : {&w0, &w1, &r0, &r1}) x->resize(whole.sizes());
    integ::Message m3;
    EXPECT_EQ(whole.residual(t, q, vk, Vec::Zero(m.nv), lambda, w1, false, m3), integ::EvalStatus::Ok);
    EXPECT_EQ(rest.residual(t, q, vk, Vec::Zero(m.nv), lambda, r1, false, m3), integ::EvalStatus::Ok);
    EXPECT_EQ(rest.residual(t, q, v, Vec::Zero(m.nv), lambda, r0, false, m3), integ::EvalStatus::Ok);
    EXPECT_EQ(whole.residual(t, q, v, Vec::Zero(m.nv), lambda, w0, false, m3), integ::EvalStatus::Ok);
    double given = 0;
    EXPECT_TRUE(whole.fastRowChange(t, k, dv, given));
    const double expected = (w1.F(i) - w0.F(i)) - (r1.F(i) - r0.F(i));
    rowError = std::max(rowError, std::abs(given - expected) / std::max(1.0, std::abs(expected)));  // N m
  }
  return std::max(rowError, (share - parts).cwiseAbs().maxCoeff() / share.cwiseAbs().maxCoeff());
}

}  // namespace

TEST(SpinColumns, TheForceLawsGiveTheColumnsTheWholeResidualGives) {
  // Near free rolling (the loaded radius turns 1.068 times the unloaded
  // one's rate) in the linear range, a locked wheel, one spinning up and one
  // in reverse (saturated); the tyres alone (the
  // brakes' 2,000 N m s/rad would hide them), with the brakes, and in the air.
  const SpinCase tyres{0.0, {1.068, 0.0, 1.6, 1.075}, false};
  const SpinCase reversed{0.0, {-0.5, 1.062, 1.07, 0.0}, false};
  const SpinCase braking{0.0, {1.068, 0.0, 1.6, 1.075}, true};
  const SpinCase inTheAir{0.5, {1.068, 0.0, 1.6, 1.075}, true};
  for (const std::string file :
       {"vehicles/sedan.toml", "vehicles/paper.toml", "vehicles/sedan_envelope.toml", "vehicles/sedan_drive.toml"}) {
    // Forward differences of a residual of ~1e4 N with increments of ~1e-6
    // rad/s carry ~1e-6 of the columns' scale; 1e-4 leaves room for that.
    for (const SpinCase& c : {tyres, reversed, braking, inTheAir}) EXPECT_LT(partsError(file, c), 1e-4) << file;
  }
}
