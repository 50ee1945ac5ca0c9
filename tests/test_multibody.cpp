// Multibody core: analytic blocks against finite differences, constraint
// levels against time derivatives, closed loops against known kinematic
// relations, conservation laws.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "integrator/bdf.h"
#include "integrator/dae_blocks.h"
#include "mechanisms.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/kinematics.h"
#include "multibody/multibody_dae.h"

using namespace bdfcar;
using integ::Mat;
using integ::Vec;

namespace {

Vec randomVector(int n, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Vec x(n);
  for (int i = 0; i < n; ++i) x(i) = u(rng);
  return x;
}

// Positions moved from neutral by a random tangent increment.
Vec randomPositions(const mb::Model& m, std::mt19937& rng, double scale) {
  Vec q0 = mb::neutralPositions(m), q(m.nq);
  mb::retract(m, q0, randomVector(m.nv, rng, scale), q);
  return q;
}

}  // namespace

TEST(Multibody, PaperTopologyHas25Coordinates14ConstraintsAnd11Dof) {
  const mb::Model m = test::paperTopology();
  EXPECT_EQ(m.nv, 25);
  EXPECT_EQ(m.nc, 14);
  EXPECT_EQ(m.nv - m.nc, 11);
  // The design configuration closes every loop.
  mb::Data d = mb::makeData(m);
  const Vec q = mb::neutralPositions(m);
  mb::updatePositions(m, q, d);
  mb::constraintPositions(m, q, d);
  EXPECT_LT(d.phi.lpNorm<Eigen::Infinity>(), 1e-14);
  // And the constraint Jacobian has full row rank there.
  Mat J(m.nc, m.nv);
  mb::constraintJacobian(m, d, J);
  Eigen::FullPivLU<Mat> lu(J);
  EXPECT_EQ(lu.rank(), 14);
}

TEST(Multibody, MassMatrixEqualsFiniteDifferenceOfResidualInAcceleration) {
  const mb::Model m = test::paperTopology();
  mb::MultibodyDae dae(m);
  std::mt19937 rng(1);
  const Vec q = randomPositions(m, rng, 0.3), v = randomVector(m.nv, rng, 2.0), a = randomVector(m.nv, rng, 5.0);
  const Vec lam = randomVector(m.nc, rng, 100.0);
  Mat Manalytic(m.nv, m.nv), Mfd(m.nv, m.nv);
  ASSERT_TRUE(dae.massMatrix(0, q, Manalytic));
  // The FD path: a DAE wrapper that declines the analytic block.
  struct NoAnalytic : integ::Dae {
    mb::MultibodyDae& d;
    explicit NoAnalytic(mb::MultibodyDae& x) : d(x) {}
    integ::DaeSizes sizes() const override { return d.sizes(); }
    void retract(const Vec& q, const Vec& dq, Vec& o) const override { d.retract(q, dq, o); }
    void localCoordinates(const Vec& b, const Vec& q, Vec& o) const override { d.localCoordinates(b, q, o); }
    void localRate(const Vec& x, const Vec& v, Vec& o) const override { d.localRate(x, v, o); }
    integ::EvalStatus residual(double t, const Vec& q, const Vec& v, const Vec& a, const Vec& l, integ::Residual& r,
                               bool c, integ::Message& msg) override {
      return d.residual(t, q, v, a, l, r, c, msg);
    }
  } fd(dae);
  integ::BlockWorkspace ws;
  ws.resize(dae.sizes());
  long count = 0;
  ASSERT_EQ(integ::massMatrixBlock(fd, 0, q, v, a, lam, Mfd, ws, count), integ::EvalStatus::Ok);
  EXPECT_EQ(count, m.nv + 1);
  EXPECT_LT((Manalytic - Mfd).norm() / Manalytic.norm(), 1e-6);
  EXPECT_LT((Manalytic - Manalytic.transpose()).norm(), 1e-9 * Manalytic.norm());
  Eigen::LLT<Mat> llt(Manalytic);
  EXPECT_EQ(llt.info(), Eigen::Success) << "mass matrix must be positive definite";
}

TEST(Multibody, ConstraintJacobianEqualsFiniteDifferenceAtAssembledConfiguration) {
  const mb::Model m = test::paperTopology();
  mb::Data d = mb::makeData(m);
  Vec q = mb::neutralPositions(m);
  // Move only the chassis (free joint): loops stay closed.
  Vec dq = Vec::Zero(m.nv);
  dq.head<6>() << 0.3, -0.2, 0.1, 0.2, -0.1, 0.7;
  Vec qc(m.nq);
  mb::retract(m, q, dq, qc);
  mb::updatePositions(m, qc, d);
  Mat J(m.nc, m.nv);
  mb::constraintJacobian(m, d, J);
  mb::constraintPositions(m, qc, d);
  const Vec phi0 = d.phi;
  EXPECT_LT(phi0.lpNorm<Eigen::Infinity>(), 1e-12);
  const double h = 1e-7;
  Mat Jfd(m.nc, m.nv);
  for (int i = 0; i < m.nv; ++i) {
    Vec e = Vec::Zero(m.nv), qp(m.nq), qm(m.nq);
    e(i) = h;
    mb::retract(m, qc, e, qp);
    mb::retract(m, qc, -e, qm);
    mb::updatePositions(m, qp, d);
    mb::constraintPositions(m, qp, d);
    const Vec pp = d.phi;
    mb::updatePositions(m, qm, d);
    mb::constraintPositions(m, qm, d);
    Jfd.col(i) = (pp - d.phi) / (2 * h);
  }
  EXPECT_LT((J - Jfd).cwiseAbs().maxCoeff(), 1e-7);
}

TEST(Multibody, VelocityAndAccelerationConstraintsAreTimeDerivatives) {
  // Along q(t) = q (+) (v t + a t^2 / 2): d/dt phi = phiDot, d/dt phiDot = phiDDot.
  const mb::Model m = test::paperTopology();
  mb::Data d = mb::makeData(m);
  std::mt19937 rng(2);
  const Vec q = randomPositions(m, rng, 0.2), v = randomVector(m.nv, rng, 1.0), a = randomVector(m.nv, rng, 3.0);
  auto eval = [&](double t, Vec& phi, Vec& phiDot, Vec& phiDDot) {
    // Exact only where the local rate is the identity: use increments of a
    // path in local coordinates and map velocities through the rate.
    Vec delta = v * t + 0.5 * a * t * t, qt(m.nq), vt(m.nv), at(m.nv);
    mb::retract(m, q, delta, qt);
    // v_t solves localRate(delta, v_t) = d delta / dt.
    const Vec ddelta = v + a * t;
    // Invert the rate numerically (it is close to identity).
    vt = ddelta;
    for (int it = 0; it < 50; ++it) {
      Vec r(m.nv);
      mb::localRate(m, delta, vt, r);
      vt -= r - ddelta;
    }
    // a_t = d v_t / dt by central difference of the same construction.
    auto vel = [&](double s) {
      Vec ds = v * s + 0.5 * a * s * s, dds = v + a * s, w = dds;
      for (int it = 0; it < 50; ++it) {
        Vec r(m.nv);
        mb::localRate(m, ds, w, r);
        w -= r - dds;
      }
      return w;
    };
    const double e = 1e-5;
    at = (vel(t + e) - vel(t - e)) / (2 * e);
    mb::updatePositions(m, qt, d);
    mb::updateVelocities(m, vt, d);
    mb::updateAccelerations(m, at, d);
    mb::constraintResiduals(m, qt, vt, at, d);
    phi = d.phi;
    phiDot = d.phiDot;
    phiDDot = d.phiDDot;
  };
  Vec p0, pd0, pdd0, pp, pdp, pddp, pm, pdm, pddm;
  const double h = 1e-4;
  eval(0.1, p0, pd0, pdd0);
  eval(0.1 + h, pp, pdp, pddp);
  eval(0.1 - h, pm, pdm, pddm);
  EXPECT_LT(((pp - pm) / (2 * h) - pd0).lpNorm<Eigen::Infinity>(), 1e-6);
  EXPECT_LT(((pdp - pdm) / (2 * h) - pdd0).lpNorm<Eigen::Infinity>(), 1e-5);
}

TEST(Multibody, ResidualIsAffineInAccelerationAndMultipliers) {
  // F(q, v, a, lambda) = M a + Phi_q^T lambda + F(q, v, 0, 0).
  const mb::Model m = test::paperTopology();
  mb::MultibodyDae dae(m);
  std::mt19937 rng(3);
  const Vec q = randomPositions(m, rng, 0.0), v = randomVector(m.nv, rng, 1.0), a = randomVector(m.nv, rng, 3.0);
  const Vec lam = randomVector(m.nc, rng, 50.0);
  integ::Residual r0, r1;
  r0.resize(dae.sizes());
  r1.resize(dae.sizes());
  integ::Message msg;
  const Vec za = Vec::Zero(m.nv), zl = Vec::Zero(m.nc);
  dae.residual(0, q, v, za, zl, r0, false, msg);
  dae.residual(0, q, v, a, lam, r1, false, msg);
  Mat M(m.nv, m.nv), J(m.nc, m.nv);
  dae.massMatrix(0, q, M);
  dae.constraintJacobian(0, q, J);
  const Vec expected = M * a + J.transpose() * lam + r0.F;
  EXPECT_LT((r1.F - expected).norm(), 1e-9 * (1 + expected.norm()));
}
