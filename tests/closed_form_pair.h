// What the closed-form rungs' tests share (test_planar_car.cpp,
// test_kinematic_car.cpp): a rack signal, a closed form and the multibody
// model it is written from side by side with the same inputs, both models'
// accelerations at one state, and the check of an analytic mass matrix
// against differences of the residual.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "integrator/forward_dynamics.h"
#include "terrain/terrain.h"
#include "vehicle/closed_form_car.h"

namespace bdfcar::testing_closed_form {

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

// Both models of one vehicle on level ground (or the terrain given), with
// the same inputs.
template <class Car>
struct Pair {
  const vehicle::Vehicle& v;
  terrain::PlaneTerrain plane;
  const terrain::Terrain& ground;
  Rack rack;
  Car car;
  mb::MultibodyDae dae;
  vehicle::VehicleForces forces;
  explicit Pair(const vehicle::Vehicle& model, const terrain::Terrain* terrain = nullptr)
      : v(model),
        ground(terrain ? *terrain : plane),
        car(model, ground),
        dae(model.model),
        forces(model, ground) {
    car.setRack(&rack);
    dae.addForceProvider(&forces);
    for (int slot = 0; slot < model.model.nDrivers; ++slot) dae.setDriverSignal(slot, &rack);
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

// Accelerations of both models at one state (the multibody model's mapped
// onto the closed form's coordinates), and what the tyres did there.
struct Accelerations {
  integ::Vec closed, multibody;
  int wheelsInContact = 0;
  double largestFriction = 0;  // |F_horizontal| / Fz of the most used tyre
};

template <class Car>
Accelerations accelerations(Pair<Car>& p, double t, const integ::Vec& q, const integ::Vec& v) {
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

// Both models' accelerations over a list of cases (each with .state and the
// rack's .rack, .rackRate, .rackAccel): the same to tolerance(case) relative
// (plus one); the cases must include a saturated tyre and a wheel in the air.
// makeState(vehicle, state, q, v) builds the closed form's state.
template <class Car, class Case, class MakeState, class Tolerance>
void expectSameAccelerations(Pair<Car>& p, const std::vector<Case>& cases, MakeState makeState, Tolerance tolerance) {
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
    const double tol = tolerance(cases[i]);
    for (int k = 0; k < p.car.coordinates(); ++k)
      EXPECT_NEAR(a.closed(k), a.multibody(k), tol * (1 + std::abs(a.multibody(k)))) << "case " << i << ", coordinate " << k;
  }
  EXPECT_TRUE(sawSaturated);
  EXPECT_TRUE(sawAirborne);
}

// The analytic mass matrix against unit differences of the residual in a
// (exact up to rounding: the residual is linear in a), and its symmetry.
inline void expectMassMatrixIsTheResidualsDerivative(vehicle::ClosedFormCar& car, double t, const integ::Vec& q,
                                                     const integ::Vec& v) {
  car.beginStep(t, q, v);
  integ::Mat M;
  ASSERT_TRUE(car.massMatrix(t, q, M));
  integ::Residual r0, r1;
  const integ::DaeSizes n = car.sizes();
  r0.resize(n);
  r1.resize(n);
  integ::Message msg;
  const integ::Vec a = integ::Vec::LinSpaced(n.nv, -2, 3), lambda;
  ASSERT_EQ(car.residual(t, q, v, a, lambda, r0, true, msg), integ::EvalStatus::Ok);
  for (int k = 0; k < n.nv; ++k) {
    integ::Vec ak = a;
    ak(k) += 1.0;
    ASSERT_EQ(car.residual(t, q, v, ak, lambda, r1, true, msg), integ::EvalStatus::Ok);
    for (int j = 0; j < n.nv; ++j) EXPECT_NEAR(r1.F(j) - r0.F(j), M(j, k), 1e-8 * (1 + M.norm())) << j << ", " << k;
  }
  EXPECT_NEAR((M - M.transpose()).norm(), 0.0, 1e-12 * M.norm());
}

// The wheel spins' Jacobian columns from the force laws alone
// (ClosedFormCar::fastColumnParts, what the BDF integrator's fast-column
// refresh takes in place of a residual per column) against the second
// algorithm they replace: forward differences of the whole residual. A spin
// column's rest (the wheel's inertia, its gyroscopic and steering
// couplings) is linear in the spins, so whole - parts is the same at any
// spins: at v and at vOther (the same state, the spins moved: tyres
// saturated, a slipping clutch). Returns the largest difference of the
// rests over the largest change of the parts between the two (which must
// be large: the tyres' slip stiffness falls tenfold when they saturate).
template <class Car>
double spinPartsError(Pair<Car>& p, double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& vOther) {
  const std::vector<int>& spins = p.car.fastColumns();
  const integ::DaeSizes n = p.car.sizes();
  integ::Message msg;
  const integ::Vec a = integ::Vec::Zero(n.nv), lambda;
  // The accepted step a tenth of a step back: the brakes' springs move with the spins.
  p.car.beginStep(t, q, v);
  p.car.forces().markAccepted(t - 0.001);
  auto rest = [&](const integ::Vec& vel, integ::Mat& parts) {
    integ::Residual r0, r1;
    r0.resize(n);
    r1.resize(n);
    EXPECT_EQ(p.car.residual(t, q, vel, a, lambda, r0, true, msg), integ::EvalStatus::Ok) << msg.c_str();
    integ::Mat whole(n.nv, static_cast<int>(spins.size()));
    for (int k = 0; k < whole.cols(); ++k) {
      integ::Vec vk = vel;
      const double h = 1.5e-8 * std::max(1.0, std::abs(vel(spins[k])));
      vk(spins[k]) += h;
      EXPECT_EQ(p.car.residual(t, q, vk, a, lambda, r1, true, msg), integ::EvalStatus::Ok) << msg.c_str();
      whole.col(k) = (r1.F - r0.F) / h;
    }
    // The parts at the state of the last residual: evaluate it there again.
    EXPECT_EQ(p.car.residual(t, q, vel, a, lambda, r0, true, msg), integ::EvalStatus::Ok) << msg.c_str();
    EXPECT_TRUE(p.car.hasFastColumnParts());
    p.car.fastColumnParts(t, parts);
    return integ::Mat(whole - parts);
  };
  integ::Mat parts, partsOther;
  const integ::Mat restHere = rest(v, parts), restThere = rest(vOther, partsOther);
  const double change = (parts - partsOther).cwiseAbs().maxCoeff();
  EXPECT_GT(change, 100.0) << "the spins moved the force laws' columns by nothing: the case tests nothing";
  // The force laws' change of each spin's own row over the whole move to
  // vOther (ClosedFormCar::fastRowChange: through saturation, not along a
  // slope) against the whole residual's change of that row less the rest's
  // (linear in the spin: its column times the move).
  double rowError = 0;
  for (int k = 0; k < static_cast<int>(spins.size()); ++k) {
    const int i = spins[k];
    const double dv = vOther(i) - v(i);
    integ::Residual r0, r1;
    r0.resize(n);
    r1.resize(n);
    integ::Vec vk = v;
    vk(i) += dv;
    EXPECT_EQ(p.car.residual(t, q, vk, a, lambda, r1, true, msg), integ::EvalStatus::Ok) << msg.c_str();
    EXPECT_EQ(p.car.residual(t, q, v, a, lambda, r0, true, msg), integ::EvalStatus::Ok) << msg.c_str();
    double given = 0;
    EXPECT_TRUE(p.car.fastRowChange(t, k, dv, given));
    const double whole = r1.F(i) - r0.F(i) - restHere(i, k) * dv;
    rowError = std::max(rowError, std::abs(given - whole) / std::max(1.0, std::abs(whole)));  // N or N m
  }
  return std::max(rowError, (restHere - restThere).cwiseAbs().maxCoeff() / change);
}

// spinPartsError over states (built by makeState as the accelerations'
// cases), each near free rolling in the tyres' linear range against a
// locked wheel, one spinning up and one in reverse (saturated); with the
// brakes off (their damping would hide the tyres) and on; a powertrain's
// clutch slipping where the car has one (Pair::inputs).
template <class Car, class State, class MakeState>
void expectSpinColumnsFromTheForceLaws(Pair<Car>& p, const std::vector<State>& states, MakeState makeState) {
  for (const bool brakes : {false, true})
    for (const State& s : states) {
      for (int w = 0; w < 4; ++w) p.inputs(w, w >= 2 ? 300.0 : 0.0, brakes ? 800.0 + 300.0 * w : 0.0);
      p.rack.travel = 0.01;
      integ::Vec q, v;
      makeState(p.v, s, q, v);
      integ::Vec vOther = v;
      const std::array<double, 4> times{0.0, 1.6, -0.5, 1.07};
      for (int w = 0; w < 4; ++w) vOther(p.car.spinV(w)) *= times[w];
      // Forward differences of a residual of ~1e4 N with increments of ~1e-6
      // rad/s carry ~1e-6 of the columns' scale; 1e-4 leaves room for that.
      EXPECT_LT(spinPartsError(p, 0.5, q, v, vOther), 1e-4) << "brakes " << brakes;
    }
}

// The analytic F_q and F_v (Dae::stateJacobian: the equations on dual
// numbers) against central differences of the residual, a second algorithm:
// the positions moved along the retraction's tangent directions, the
// velocities directly. Returns the largest difference of an entry over its
// column's largest entry (plus one); whether a tyre was saturated or off
// the ground at the state goes into seen (the cases must include both).
struct Seen {
  bool saturated = false, airborne = false;
};
// A tyre's peak friction at its load Fz on road friction mu (a Magic
// Formula's falls with the load: tyre::peakFriction is its largest).
inline double peakAtLoad(const tyre::TyreParams& t, double Fz, double mu) {
  if (const auto* pac = std::get_if<tyre::Pac2002Params>(&t)) {
    const tyre::MagicFormulaForces f = tyre::magicFormula(*pac, 0.0, 0.0, 0.0, Fz, mu);
    return std::max(std::abs(f.Dx), std::abs(f.Dy)) / Fz;
  }
  return tyre::peakFriction(t, mu);
}
// The step's ground (its planes, an enveloping tyre's profile) is cast at
// `predicted` (the state itself when null), as a step's prediction lies
// off the iterates: an enveloping tyre's profile has a sample under the
// predicted wheel centre, where its lateral slope has a kink (linear between
// samples), which differences across would not differentiate.
template <class Car>
double stateJacobianError(Pair<Car>& p, double t, const integ::Vec& q, const integ::Vec& v, Seen& seen,
                          const integ::Vec* predicted = nullptr) {
  const integ::DaeSizes n = p.car.sizes();
  integ::Residual r0, rp, rm;
  r0.resize(n);
  rp.resize(n);
  rm.resize(n);
  integ::Message msg;
  const integ::Vec a = integ::Vec::LinSpaced(n.nv, -1, 2), lambda;
  p.car.beginStep(t, predicted ? *predicted : q, v);
  p.car.forces().markAccepted(t - 0.004);  // inside a step: the brakes' springs and the clutch move with the spins
  auto residual = [&](const integ::Vec& qs, const integ::Vec& vs, integ::Residual& r) {
    EXPECT_EQ(p.car.residual(t, qs, vs, a, lambda, r, true, msg), integ::EvalStatus::Ok) << msg.c_str();
  };
  residual(q, v, r0);
  for (int w = 0; w < 4; ++w) {
    const tyre::TyreOutput& o = p.car.forces().outputs()[w].out;
    if (!o.inContact || o.Fz < 50.0) seen.airborne = true;
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), centre = p.car.wheelCentre(w);
    const double mu = p.ground.castRay(centre + up, -up, 3.0).friction;
    if (o.inContact && o.Fz > 0 && std::hypot(o.Fx, o.Fy) > 0.95 * peakAtLoad(p.v.wheel(w).tyre, o.Fz, mu) * o.Fz)
      seen.saturated = true;
  }
  integ::Mat Fq(n.nv, n.nv), Fv(n.nv, n.nv);
  EXPECT_TRUE(p.car.stateJacobian(t, q, v, a, Fq, Fv));
  integ::Mat differencedQ(n.nv, n.nv), differencedV(n.nv, n.nv);
  integ::Vec dq = integ::Vec::Zero(n.nv), qp(n.nq), qm(n.nq);
  for (int k = 0; k < n.nv; ++k) {
    // Central differences extrapolated (Richardson: (4 D(h/2) - D(h)) / 3):
    // truncation h^4 F^(5), rounding 1e-16 |F| / h. A tyre near its
    // saturation curves enough that a plain central difference's h^2 F'''
    // is a few 1e-6 of a column at h = 1e-6.
    auto central = [&](int k, double h, bool position) -> integ::Vec {
      if (position) {
        dq(k) = h;
        p.car.retract(q, dq, qp);
        dq(k) = -h;
        p.car.retract(q, dq, qm);
        dq(k) = 0;
        residual(qp, v, rp);
        residual(qm, v, rm);
      } else {
        integ::Vec vp = v, vm = v;
        vp(k) += h;
        vm(k) -= h;
        residual(q, vp, rp);
        residual(q, vm, rm);
      }
      return (rp.F - rm.F) / (2 * h);
    };
    const double hq = 1e-6, hv = 1e-6 * std::max(1.0, std::abs(v(k)));
    differencedQ.col(k) = (4 * central(k, 0.5 * hq, true) - central(k, hq, true)) / 3;
    differencedV.col(k) = (4 * central(k, 0.5 * hv, false) - central(k, hv, false)) / 3;
  }
  // Each column against its own largest entry, but not below a thousandth
  // of the block's (a column that is zero but for the differences' rounding
  // of a ~1e4 N residual, ~1e-6, has nothing to be relative to).
  auto error = [](const integ::Mat& exact, const integ::Mat& differenced) {
    const double floor = 1e-3 * differenced.cwiseAbs().maxCoeff();
    double worst = 0;
    for (int k = 0; k < exact.cols(); ++k)
      worst = std::max(worst, (exact.col(k) - differenced.col(k)).cwiseAbs().maxCoeff() /
                                  std::max(floor, differenced.col(k).cwiseAbs().maxCoeff()));
    return worst;
  };
  const double worst = std::max(error(Fq, differencedQ), error(Fv, differencedV));
  if (std::getenv("BDFCAR_JACOBIAN_TRACE"))
    for (int i = 0; i < n.nv; ++i)
      for (int k = 0; k < n.nv; ++k)
        std::printf("  F%d / q%d %.9g (differenced %.9g), / v%d %.9g (differenced %.9g)\n", i, k, Fq(i, k),
                    differencedQ(i, k), k, Fv(i, k), differencedV(i, k));
  residual(q, v, r0);  // the force laws' inputs back at the state
  return worst;
}

// stateJacobianError over cases (a state for makeState and the rack's
// travel), within tolerance each; the rear wheels driven, the brakes on in
// the second case, the rack moving in the fifth; the states at x (as made
// where absent), the ground cast predictedAhead behind them. The cases must
// include a saturated tyre and a wheel in the air.
template <class Car, class State, class MakeState>
void expectStateJacobians(Pair<Car>& p, const std::vector<std::pair<State, double>>& cases, MakeState makeState,
                          double tolerance, std::optional<double> x = std::nullopt, double predictedAhead = 0.0) {
  Seen seen;
  for (size_t i = 0; i < cases.size(); ++i) {
    for (int w = 0; w < 4; ++w) p.inputs(w, w >= 2 ? 300.0 : 0.0, i == 1 ? 800.0 : 0.0);
    p.rack.travel = cases[i].second;
    p.rack.rate = i == 4 ? 0.05 : 0.0;
    integ::Vec q, v;
    makeState(p.v, cases[i].first, q, v);
    if (x) q(0) = *x;
    integ::Vec predicted = q;
    predicted(0) -= predictedAhead;
    const double error = stateJacobianError(p, 0.5, q, v, seen, &predicted);
    std::printf("case %zu: largest difference %.2g of its column\n", i, error);
    EXPECT_LT(error, tolerance) << "case " << i;
  }
  EXPECT_TRUE(seen.saturated);
  EXPECT_TRUE(seen.airborne);
}

}  // namespace bdfcar::testing_closed_form
