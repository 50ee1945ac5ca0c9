// BDF on the over-determined DAE and the explicit comparison integrators,
// against analytic solutions, kinematic relations, conservation laws and an
// independent reference integration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "integrator/bdf.h"
#include "integrator/explicit.h"
#include "mechanisms.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/kinematics.h"
#include "multibody/multibody_dae.h"

using namespace bdfcar;
using integ::Vec;

namespace {

integ::BdfOptions tightOptions(int order) {
  integ::BdfOptions o;
  o.order = order;
  o.newtonIterations = 0;  // to tolerance
  o.atol = 1e-12;
  o.rtol = 1e-10;
  o.jacobianEvery = 1;
  o.maxNewtonIterations = 20;
  return o;
}

// Pendulum angle: the revolute coordinate about +y; the bob hangs at q = 0.
struct PendulumRun {
  mb::Model model = test::pendulum(1.0, 2.0, 0.1);
  mb::MultibodyDae dae{model};
};

// Independent reference: classic RK4 on theta'' = -(m g L / I) sin(theta), tiny step.
double referencePendulum(double theta0, double omega0, double k, double T, double h = 1e-5) {
  double th = theta0, w = omega0;
  const int n = static_cast<int>(std::llround(T / h));
  auto f = [k](double t) { return -k * std::sin(t); };
  for (int i = 0; i < n; ++i) {
    const double k1t = w, k1w = f(th);
    const double k2t = w + 0.5 * h * k1w, k2w = f(th + 0.5 * h * k1t);
    const double k3t = w + 0.5 * h * k2w, k3w = f(th + 0.5 * h * k2t);
    const double k4t = w + h * k3w, k4w = f(th + h * k3t);
    th += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
    w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
  }
  return th;
}

}  // namespace

TEST(Bdf, PendulumLargeAmplitudePeriodMatchesEllipticIntegral) {
  PendulumRun p;
  const double L = 1.0, m = 2.0, rg = 0.1, g = 9.81;
  const double I = m * (L * L + rg * rg);
  const double theta0 = 150.0 * std::numbers::pi / 180.0;
  // Exact period of the physical pendulum: T = 4 sqrt(I / (m g L)) K(sin(theta0 / 2)).
  const double Texact = 4.0 * std::sqrt(I / (m * g * L)) * std::comp_ellint_1(std::sin(theta0 / 2));
  integ::BdfIntegrator bdf(p.dae, tightOptions(3));
  Vec q(1), v(1);
  q << theta0;
  v << 0.0;
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok) << msg.c_str();
  // Find the downward zero crossings of the velocity (turning points at +theta0).
  const double h = 1e-3;
  std::vector<double> peaks;
  double vPrev = 0;
  for (int i = 0; i < 20000 && peaks.size() < 3; ++i) {
    const auto rep = bdf.step(h);
    ASSERT_TRUE(rep.ok()) << rep.message.c_str();
    const double vNow = bdf.current().v(0);
    if (i > 0 && vPrev > 0 && vNow <= 0) peaks.push_back(bdf.current().t - h * vNow / (vNow - vPrev));
    vPrev = vNow;
  }
  ASSERT_EQ(peaks.size(), 3u);
  const double T = (peaks[2] - peaks[0]) / 2;
  EXPECT_NEAR(T, Texact, 1e-4 * Texact) << "measured " << T << " exact " << Texact;
}

TEST(Bdf, OrderOfConvergenceOnPendulum) {
  // Global error at t = 1 s against an independent RK4 reference, for BDF 1-3:
  // the log-log slope over h, h/2, h/4 must be within 0.2 of the order.
  const double theta0 = 1.0, k = 9.81 * 2.0 * 1.0 / (2.0 * (1.0 + 0.01));
  const double Tend = 1.0, ref = referencePendulum(theta0, 0.0, k, Tend);
  for (int order = 1; order <= 3; ++order) {
    std::vector<double> err;
    for (double h : {0.01, 0.005, 0.0025}) {
      PendulumRun p;
      integ::BdfIntegrator bdf(p.dae, tightOptions(order));
      Vec q(1), v(1);
      q << theta0;
      v << 0.0;
      integ::Message msg;
      ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
      const int n = static_cast<int>(std::llround(Tend / h));
      for (int i = 0; i < n; ++i) ASSERT_TRUE(bdf.step(h).ok());
      err.push_back(std::abs(bdf.current().q(0) - ref));
    }
    const double slope = std::log2(err[0] / err[2]) / 2.0;
    EXPECT_NEAR(slope, order, 0.2) << "BDF" << order << " errors " << err[0] << " " << err[1] << " " << err[2];
  }
}

TEST(Bdf, FourBarClosesLoopEveryStepAndObeysFreudenstein) {
  const test::FourBar fb = test::fourBar(0.1, 0.35, 0.25, 0.3, 1.2);
  mb::MultibodyDae dae(fb.model);
  integ::BdfIntegrator bdf(dae, tightOptions(2));
  // Consistent start: crank spinning, rocker velocity from Phi_q v = 0.
  Vec q = mb::neutralPositions(fb.model), v(2);
  mb::Data d = mb::makeData(fb.model);
  mb::updatePositions(fb.model, q, d);
  Eigen::MatrixXd J(1, 2);
  mb::constraintJacobian(fb.model, d, J);
  v << 8.0, -8.0 * J(0, 0) / J(0, 1);
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  const double K1 = fb.d / fb.a, K2 = fb.d / fb.c;
  const double K3 = (fb.a * fb.a - fb.b * fb.b + fb.c * fb.c + fb.d * fb.d) / (2 * fb.a * fb.c);
  double worstPhi = 0, worstPhiDot = 0, worstPhiDDot = 0, worstFreud = 0;
  for (int i = 0; i < 2000; ++i) {
    ASSERT_TRUE(bdf.step(1e-3).ok());
    const auto& s = bdf.current();
    mb::updatePositions(fb.model, s.q, d);
    mb::updateVelocities(fb.model, s.v, d);
    mb::updateAccelerations(fb.model, s.a, d);
    mb::constraintResiduals(fb.model, s.q, s.v, s.a, d);
    worstPhi = std::max(worstPhi, std::abs(d.phi(0)));
    worstPhiDot = std::max(worstPhiDot, std::abs(d.phiDot(0)));
    worstPhiDDot = std::max(worstPhiDDot, std::abs(d.phiDDot(0)));
    const double t2 = fb.crank0 + s.q(0), t4 = fb.rocker0 + s.q(1);
    worstFreud = std::max(worstFreud, std::abs(K1 * std::cos(t4) - K2 * std::cos(t2) + K3 - std::cos(t2 - t4)));
  }
  EXPECT_LT(worstPhi, 1e-10);
  EXPECT_LT(worstPhiDot, 1e-10);
  EXPECT_LT(worstPhiDDot, 1e-10);
  EXPECT_LT(worstFreud, 1e-8);
  // The crank went round at least once (a real motion, not a standstill).
  EXPECT_GT(std::abs(bdf.current().q(0)), 2 * std::numbers::pi);
}

TEST(Bdf, SliderCrankWithSphericalCutJointFollowsKinematics) {
  const double a = 0.1, b = 0.3;
  const mb::Model m = test::sliderCrank(a, b);
  mb::MultibodyDae dae(m);
  integ::BdfIntegrator bdf(dae, tightOptions(2));
  Vec q = mb::neutralPositions(m), v = Vec::Zero(m.nv);
  // q = [crank, rod quaternion (4), slider]; v = [crank, rod w (3), slider].
  // At the dead centre the slider is at rest and the rod rotates with -crank
  // rate about y: rod tip speed = crank tip speed.
  v(0) = 10.0;
  v(2) = -10.0 * a / b;
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok) << msg.c_str();
  mb::Data d = mb::makeData(m);
  double worstPhi = 0, worstRelation = 0;
  for (int i = 0; i < 1500; ++i) {
    const auto rep = bdf.step(1e-3);
    ASSERT_TRUE(rep.ok()) << rep.message.c_str();
    const auto& s = bdf.current();
    mb::updatePositions(m, s.q, d);
    mb::constraintPositions(m, s.q, d);
    worstPhi = std::max(worstPhi, d.phi.lpNorm<Eigen::Infinity>());
    // Crank angle about +y: tip at a (cos t, 0, -sin t); slider along x at z = 0.
    const double t = s.q(0);
    const double xExpected = a * std::cos(t) + std::sqrt(b * b - a * a * std::sin(t) * std::sin(t));
    const double xSlider = a + b + s.q(m.bodies[2].qIndex);
    worstRelation = std::max(worstRelation, std::abs(xSlider - xExpected));
  }
  EXPECT_LT(worstPhi, 1e-10);
  EXPECT_LT(worstRelation, 1e-9);
}

TEST(Bdf, TorqueFreeBodyConservesMomentumAndEnergyThroughFlips) {
  // Spin near the intermediate axis: the body flips over repeatedly
  // (Dzhanibekov); angular momentum in the world and kinetic energy stay.
  const mb::Model m = test::freeBody(1.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  mb::MultibodyDae dae(m);
  integ::BdfIntegrator bdf(dae, tightOptions(3));
  Vec q = mb::neutralPositions(m), v = Vec::Zero(6);
  v.segment<3>(0) << 0.3, -0.2, 0.1;    // linear velocity (body frame)
  v.segment<3>(3) << 0.02, 4.0, 0.02;   // angular velocity (body frame)
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  mb::Data d = mb::makeData(m);
  auto momentum = [&](const Vec& qq, const Vec& vv) {
    mb::updatePositions(m, qq, d);
    const Eigen::Vector3d w = vv.segment<3>(3);
    return Eigen::Vector3d(d.R[0] * (m.bodies[0].inertia * w));
  };
  auto energy = [&](const Vec& vv) {
    const Eigen::Vector3d w = vv.segment<3>(3), u = vv.segment<3>(0);
    return 0.5 * w.dot(m.bodies[0].inertia * w) + 0.5 * u.squaredNorm();
  };
  const Eigen::Vector3d L0 = momentum(q, v);
  const double E0 = energy(v);
  double minYAxisAlignment = 1;
  for (int i = 0; i < 10000; ++i) {
    ASSERT_TRUE(bdf.step(1e-3).ok());
    const auto& s = bdf.current();
    EXPECT_LT((momentum(s.q, s.v) - L0).norm(), 1e-5 * L0.norm()) << "t = " << s.t;
    EXPECT_LT(std::abs(energy(s.v) - E0), 1e-5 * E0);
    mb::updatePositions(m, s.q, d);
    minYAxisAlignment = std::min(minYAxisAlignment, d.R[0].col(1).dot(L0.normalized()));
    if (::testing::Test::HasFailure()) break;
  }
  // The body axis y turned against the momentum at least once: it flipped.
  EXPECT_LT(minYAxisAlignment, -0.9);
  // Free flight: the centre of mass moves in a straight line at constant speed.
  mb::updatePositions(m, bdf.current().q, d);
  EXPECT_NEAR(d.p[0].norm(), 10.0 * std::sqrt(0.14), 1e-6);
}

TEST(Bdf, JacobianEvery200StepsOver400StepsGivesTwoJacobiansAndTwoFactorizations) {
  PendulumRun p;
  integ::BdfOptions o;
  o.order = 1;
  o.newtonIterations = 2;
  o.jacobianEvery = 200;
  o.refreshWhenNotContracting = false;
  integ::BdfIntegrator bdf(p.dae, o);
  Vec q(1), v(1);
  q << 0.5;
  v << 0.0;
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  const long residualsBefore = bdf.counters().residuals;
  for (int i = 0; i < 400; ++i) ASSERT_TRUE(bdf.step(0.01).ok());
  const auto& c = bdf.counters();
  EXPECT_EQ(c.steps, 400);
  EXPECT_EQ(c.jacobians, 2);
  EXPECT_EQ(c.factorizations, 2 + 1);  // + the consistent-acceleration solve at initialize
  EXPECT_EQ(c.newtonIterations, 800);
  EXPECT_EQ(c.residuals - residualsBefore, 800);
  EXPECT_EQ(c.solves - 1, 3 * 800);    // three solves per iteration, one LU
  // Finite-difference Jacobian: 2 nv + 1 residuals each (F_a and Phi_q are analytic).
  EXPECT_EQ(c.jacobianResiduals, 2 * (2 * 1 + 1));
}

namespace {

// A mass on a spring of stiffness k + 3 k3 x^2 (Duffing's), no constraints
// (as a closed-form rung): linear for k3 = 0, where the iteration matrix
// never changes and Newton's correction after the first is roundoff.
class DuffingOscillator final : public integ::Dae {
 public:
  explicit DuffingOscillator(double k3) : k3_(k3) {}
  integ::DaeSizes sizes() const override { return {1, 1, 0}; }
  void retract(const Vec& q, const Vec& dq, Vec& out) const override { out = q + dq; }
  void localCoordinates(const Vec& base, const Vec& q, Vec& out) const override { out = q - base; }
  void localRate(const Vec&, const Vec& v, Vec& out) const override { out = v; }
  integ::EvalStatus residual(double, const Vec& q, const Vec& v, const Vec& a, const Vec&, integ::Residual& out,
                             bool, integ::Message&) override {
    out.F(0) = a(0) + 0.5 * v(0) + 1000.0 * q(0) + k3_ * q(0) * q(0) * q(0);
    return integ::EvalStatus::Ok;
  }

 private:
  double k3_;
};

struct PolicyRun {
  integ::Counters counters;
  double x = 0;  // at the end
};

PolicyRun runDuffing(double k3, bool refreshWhenNotContracting, int jacobianEvery,
                     const std::function<void(integ::BdfOptions&)>& adjust = {}, std::vector<double>* path = nullptr,
                     double h = 0.01) {
  DuffingOscillator dae(k3);
  integ::BdfOptions o;
  o.newtonIterations = 2;  // in full: every step measures Newton's contraction
  o.jacobianEvery = jacobianEvery;
  o.refreshWhenNotContracting = refreshWhenNotContracting;
  if (adjust) adjust(o);
  integ::BdfIntegrator bdf(dae, o);
  Vec q(1), v(1);
  q << 1.0;
  v << 0.0;
  integ::Message msg;
  EXPECT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  const int steps = static_cast<int>(std::lround(4.0 / h));
  for (int i = 0; i < steps; ++i) {
    EXPECT_TRUE(bdf.step(h).ok());
    if (path) path->push_back(bdf.current().q(0));
  }
  return {bdf.counters(), bdf.current().q(0)};
}

}  // namespace

TEST(Bdf, WithoutConstraintsThePeriodicJacobianWaitsForNewtonToSayItIsStale) {
  // Linear: the blocks of the first step are those of every step, so the
  // periodic Jacobian (every 20 steps) is never due, and the run is the
  // one with a Jacobian at every step (Newton's second correction is
  // roundoff); the paper's policy (no refresh on a slow contraction) takes
  // it at every 20th step.
  const PolicyRun linear = runDuffing(0.0, true, 20), fresh = runDuffing(0.0, true, 1);
  EXPECT_EQ(linear.counters.jacobians, 1);
  EXPECT_EQ(fresh.counters.jacobians, 400);
  EXPECT_NEAR(linear.x, fresh.x, 1e-12);
  EXPECT_EQ(runDuffing(0.0, false, 20).counters.jacobians, 20);
  // Hardening from 1000 to 10,000 N/m over the swing: a Jacobian taken at
  // one end of it is stale at the other, Newton says so (it contracts
  // linearly), and the periodic one is taken again; never retaken, the
  // same run needs more iterations.
  const PolicyRun hard = runDuffing(3000.0, true, 20), never = runDuffing(3000.0, true, 0);
  EXPECT_GT(hard.counters.jacobians - hard.counters.rescues - hard.counters.refreshes, 1);
  EXPECT_LT(hard.counters.newtonIterations, never.counters.newtonIterations);
}

TEST(Bdf, TheEarlyEndFromTheContractionEndsWhereTheIterateIsWithinTolerance) {
  // Hardening (the stiffness 1000 -> 2500 N/m over the swing), the
  // Jacobian of the first step only: a chord iteration contracting at a
  // steady rate. Ending the count where the correction is within tolerance
  // takes a second residual at the steps whose first correction is a few
  // tolerances; judged by the iterate (the contraction's error estimate,
  // BdfOptions::earlyEndFromContraction), most of them end at one. Each
  // step's iterate is checked against the same step (the same history)
  // solved by Newton to a tolerance far below: within tolerance, in the
  // integrator's own norm (the weighted RMS of [dq; h' dv]).
  const double h = 0.01, tol = 1e-3;
  DuffingOscillator dae(500.0), probeDae(500.0);
  auto options = [&](bool fromContraction) {
    integ::BdfOptions o;
    o.newtonIterations = 2;
    o.jacobianEvery = 0;
    o.stopWithinTolerance = true;
    o.earlyEndFromContraction = fromContraction;
    o.atol = o.rtol = tol;
    return o;
  };
  integ::BdfOptions exactOptions;
  exactOptions.newtonIterations = 0;  // to tolerance, and far below the step's
  exactOptions.atol = exactOptions.rtol = 1e-12;
  exactOptions.jacobianEvery = 1;
  long residuals[2] = {0, 0};
  double worst = 0;
  int endedEarly = 0;
  for (bool fromContraction : {false, true}) {
    integ::IntegratorState state;
    integ::BdfIntegrator bdf(dae, options(fromContraction)), exact(probeDae, exactOptions);
    bdf.bindState(state);
    Vec q(1), v(1);
    q << 1.0;
    v << 0.0;
    integ::Message msg;
    ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
    for (int i = 0; i < 2000; ++i) {
      integ::IntegratorState probe = state;
      const integ::StepReport rep = bdf.step(h);
      ASSERT_TRUE(rep.ok());
      if (!fromContraction || i < 2) continue;  // (the start-up's steps are of order one)
      endedEarly += rep.iterations == 1 && rep.correction > 1.0;
      exact.bindState(probe);
      ASSERT_TRUE(exact.step(h).ok());
      const integ::SolutionPoint &got = state.node(0), &solved = probe.node(0), &before = probe.node(1);
      const double w = 1.0 / (tol + tol * std::abs(solved.q(0) - before.q(0)));
      const double hPrime = 2.0 * h / 3.0;  // BDF2 on a uniform grid
      const double dq = (got.q(0) - solved.q(0)) * w, dv = hPrime * (got.v(0) - solved.v(0)) * w;
      worst = std::max(worst, std::sqrt(0.5 * (dq * dq + dv * dv)));
    }
    residuals[fromContraction] = bdf.counters().newtonIterations;
  }
  std::printf("residuals: plain early end %ld, judged by the iterate %ld (%d steps ended at a correction above "
              "tolerance); the iterates' largest error %.3g tolerances\n",
              residuals[0], residuals[1], endedEarly, worst);
  EXPECT_GT(endedEarly, 200);
  EXPECT_LT(residuals[1], residuals[0] - 200);
  EXPECT_LE(worst, 1.0);
}

TEST(Bdf, OrderTwoStartsAtOrderOneAndRefactorsOnceForTheNewStepCoefficient) {
  PendulumRun p;
  integ::BdfOptions o;
  o.order = 2;
  o.newtonIterations = 2;
  o.jacobianEvery = 0;  // first step only
  integ::BdfIntegrator bdf(p.dae, o);
  Vec q(1), v(1);
  q << 0.5;
  v << 0.0;
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(bdf.step(0.01).ok());
  EXPECT_EQ(bdf.counters().jacobians, 1);
  // Order 1 (h' = h), then order 2 (h' = 2h/3): two factorizations + initialize.
  EXPECT_EQ(bdf.counters().factorizations, 3);
}

TEST(Bdf, RunsAreBitIdentical) {
  auto run = [] {
    const mb::Model m = test::paperTopology();
    mb::MultibodyDae dae(m);
    integ::BdfOptions o;
    o.order = 2;
    o.newtonIterations = 2;
    o.jacobianEvery = 50;
    integ::BdfIntegrator bdf(dae, o);
    Vec q = mb::neutralPositions(m), v = Vec::Zero(m.nv);
    v(0) = 5.0;  // chassis moving forward
    integ::Message msg;
    bdf.initialize(0, q, v, msg);
    for (int i = 0; i < 200; ++i) bdf.step(0.01);
    const auto& s = bdf.current();
    Vec all(s.q.size() + s.v.size() + s.a.size() + s.lambda.size());
    all << s.q, s.v, s.a, s.lambda;
    return all;
  };
  const Vec a = run(), b = run();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * a.size()), 0);
}

TEST(Bdf, ConvergedStepSatisfiesAllConstraintLevelsAndTangentBdfRelations) {
  // The vehicle-sized closed loop falling under gravity with springs:
  // after a converged step all three constraint levels hold to round-off.
  const mb::Model m = test::paperTopology();
  mb::MultibodyDae dae(m);
  integ::BdfIntegrator bdf(dae, tightOptions(2));
  Vec q = mb::neutralPositions(m), v = Vec::Zero(m.nv);
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  mb::Data d = mb::makeData(m);
  for (int i = 0; i < 50; ++i) {
    const auto rep = bdf.step(0.005);
    ASSERT_TRUE(rep.ok()) << rep.message.c_str();
    const auto& s = bdf.current();
    mb::updatePositions(m, s.q, d);
    mb::updateVelocities(m, s.v, d);
    mb::updateAccelerations(m, s.a, d);
    mb::constraintResiduals(m, s.q, s.v, s.a, d);
    EXPECT_LT(d.phi.lpNorm<Eigen::Infinity>(), 1e-10);
    EXPECT_LT(d.phiDot.lpNorm<Eigen::Infinity>(), 1e-10);
    EXPECT_LT(d.phiDDot.lpNorm<Eigen::Infinity>(), 1e-10);
  }
  // The suspension actually moved (springs are not at their free length).
  EXPECT_GT(bdf.current().v.tail(m.nv - 6).lpNorm<Eigen::Infinity>(), 1e-3);
}

TEST(Explicit, Rk4IsFourthOrderAndSemiImplicitEulerFirstOrderOnPendulum) {
  const double theta0 = 1.0, k = 9.81 * 2.0 * 1.0 / (2.0 * (1.0 + 0.01));
  const double Tend = 1.0, ref = referencePendulum(theta0, 0.0, k, Tend);
  for (auto method : {integ::ExplicitMethod::RK4, integ::ExplicitMethod::SemiImplicitEuler}) {
    std::vector<double> err;
    for (double h : {0.02, 0.01, 0.005}) {
      PendulumRun p;
      integ::ExplicitOptions o;
      o.method = method;
      integ::ExplicitIntegrator ex(p.dae, o);
      Vec q(1), v(1);
      q << theta0;
      v << 0.0;
      integ::Message msg;
      ASSERT_EQ(ex.initialize(0, q, v, msg), integ::EvalStatus::Ok);
      const int n = static_cast<int>(std::llround(Tend / h));
      for (int i = 0; i < n; ++i) ASSERT_TRUE(ex.step(h).ok());
      err.push_back(std::abs(ex.current().q(0) - ref));
    }
    const double slope = std::log2(err[0] / err[2]) / 2.0;
    const double order = method == integ::ExplicitMethod::RK4 ? 4.0 : 1.0;
    EXPECT_NEAR(slope, order, 0.25) << "errors " << err[0] << " " << err[1] << " " << err[2];
  }
}
