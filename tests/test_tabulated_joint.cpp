// Tabulated joints (reduced models derived from a linkage) against the exact
// joints they tabulate: a universal joint with an offset body and a
// point-to-point spring, sampled on a grid, must give the same kinematics and
// inverse dynamics as the universal joint itself, up to the spline's
// interpolation error. The spline grid itself against a smooth function and
// against finite differences of its own values.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "multibody/data.h"
#include "multibody/dynamics.h"
#include "multibody/kinematics.h"
#include "multibody/multibody_dae.h"
#include "multibody/model_error.h"
#include "multibody/spline_grid.h"
#include "autodiff.h"

namespace bdfcar::mb {
namespace {

double smooth(double x, double y) { return std::sin(1.3 * x) * std::cos(0.7 * y) + 0.2 * x * y * y; }

TEST(SplineGrid, ReproducesASmoothFunctionAndItsDerivatives) {
  const GridAxis ax{-1.0, 0.05, 41}, ay{-0.5, 0.05, 21};
  std::vector<std::vector<double>> samples(1, std::vector<double>(ax.nodes * ay.nodes));
  for (int j = 0; j < ay.nodes; ++j)
    for (int i = 0; i < ax.nodes; ++i)
      samples[0][i + ax.nodes * j] = smooth(ax.start + i * ax.step, ay.start + j * ay.step);
  const SplineGrid g(ax, ay, samples);
  SplineGrid::Sample s, sp, sm;
  // Interior points away from the natural ends: the value to O(h^4), first
  // derivatives to O(h^3).
  for (double x : {-0.61, -0.13, 0.02, 0.37, 0.58})
    for (double y : {-0.27, 0.04, 0.21}) {
      g.eval(x, y, s);
      EXPECT_NEAR(s.f[0], smooth(x, y), 2e-6) << x << " " << y;
      EXPECT_NEAR(s.grad[0][0], 1.3 * std::cos(1.3 * x) * std::cos(0.7 * y) + 0.2 * y * y, 2e-4);
      EXPECT_NEAR(s.grad[0][1], -0.7 * std::sin(1.3 * x) * std::sin(0.7 * y) + 0.4 * x * y, 2e-4);
      EXPECT_FALSE(s.outside);
      // The gradient and Hessian are those of the interpolant itself (central differences).
      const double e = 1e-6;
      g.eval(x + e, y, sp);
      g.eval(x - e, y, sm);
      EXPECT_NEAR(s.grad[0][0], (sp.f[0] - sm.f[0]) / (2 * e), 1e-7);
      EXPECT_NEAR(s.hess[0][0], (sp.grad[0][0] - sm.grad[0][0]) / (2 * e), 1e-5);
      EXPECT_NEAR(s.hess[0][1], (sp.grad[0][1] - sm.grad[0][1]) / (2 * e), 1e-5);
      g.eval(x, y + e, sp);
      g.eval(x, y - e, sm);
      EXPECT_NEAR(s.grad[0][1], (sp.f[0] - sm.f[0]) / (2 * e), 1e-7);
      EXPECT_NEAR(s.hess[0][2], (sp.grad[0][1] - sm.grad[0][1]) / (2 * e), 1e-5);
    }
}

TEST(SplineGrid, ContinuesLinearlyAndContinuouslyBeyondTheGrid) {
  const GridAxis ax{0.0, 0.1, 11};
  std::vector<std::vector<double>> samples(1, std::vector<double>(ax.nodes));
  for (int i = 0; i < ax.nodes; ++i) samples[0][i] = std::exp(ax.start + i * ax.step);
  const SplineGrid g(ax, GridAxis{0, 1, 1}, samples);
  SplineGrid::Sample in, edge, out1, out2;
  g.eval(1.0 - 1e-9, 0, in);
  g.eval(1.0, 0, edge);
  g.eval(1.2, 0, out1);
  g.eval(1.4, 0, out2);
  EXPECT_NEAR(in.f[0], edge.f[0], 1e-8);
  EXPECT_NEAR(in.grad[0][0], edge.grad[0][0], 1e-6);
  EXPECT_TRUE(out1.outside);
  EXPECT_NEAR(out1.f[0], edge.f[0] + 0.2 * edge.grad[0][0], 1e-12);
  EXPECT_NEAR(out2.f[0] - out1.f[0], out1.f[0] - edge.f[0], 1e-12);
  EXPECT_EQ(out1.hess[0][0], 0.0);
}

TEST(SplineGrid, RowCachedEvaluationIsTheDirectOne) {
  // Many x at one y through the row cache (the cell contracted along y once)
  // against the direct tensor-product evaluation: the same function, the
  // sums in another order. Across cells, at a changed y, and beyond the grid.
  const GridAxis ax{-1.0, 0.05, 41}, ay{-0.5, 0.05, 21};
  std::vector<std::vector<double>> samples(3, std::vector<double>(ax.nodes * ay.nodes));
  for (int j = 0; j < ay.nodes; ++j)
    for (int i = 0; i < ax.nodes; ++i) {
      const double x = ax.start + i * ax.step, y = ay.start + j * ay.step;
      samples[0][i + ax.nodes * j] = smooth(x, y);
      samples[1][i + ax.nodes * j] = std::exp(0.5 * x - y);
      samples[2][i + ax.nodes * j] = x * x * y;
    }
  const SplineGrid g(ax, ay, samples);
  SplineGrid::RowCache cache;
  SplineGrid::Sample direct, cached;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-1.2, 1.2), uy(-0.6, 0.6);
  int hits = 0;
  for (int n = 0; n < 400; ++n) {
    const double y = n % 20 == 0 ? uy(rng) : cache.y, x = n % 3 == 0 ? ux(rng) : ux(rng) * 0.008 + 0.325;  // within one cell
    const int before = cache.i;
    g.eval(x, y, direct);
    g.eval(x, y, cache, cached);
    hits += cache.i == before && y == cache.y ? 1 : 0;
    EXPECT_EQ(direct.outside, cached.outside);
    for (int c = 0; c < 3; ++c) {
      const double scale = 1 + std::abs(direct.f[c]);
      EXPECT_NEAR(cached.f[c], direct.f[c], 1e-12 * scale) << x << " " << y;
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(cached.grad[c][k], direct.grad[c][k], 1e-11 * (1 + std::abs(direct.grad[c][k])));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(cached.hess[c][k], direct.hess[c][k], 1e-10 * (1 + std::abs(direct.hess[c][k])));
    }
  }
  EXPECT_GT(hits, 100);  // evaluations where x stayed in the cached cell at the same y
}

TEST(SplineGrid, CachedCellOfOneCoordinateIsTheDirectSpline) {
  // One coordinate (a rear corner's table over its travel): the cell's
  // cubics kept in the cache against the direct Hermite evaluation, across
  // cells and beyond the grid, the Dual's derivative too.
  const GridAxis ax{-0.1, 0.01, 21};
  std::vector<std::vector<double>> samples(2, std::vector<double>(ax.nodes));
  for (int i = 0; i < ax.nodes; ++i) {
    const double x = ax.start + i * ax.step;
    samples[0][i] = std::sin(20 * x) + x * x;
    samples[1][i] = std::exp(3 * x);
  }
  const SplineGrid g(ax, GridAxis{0, 1, 1}, samples);
  SplineGrid::RowCache cache;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(-0.13, 0.13);
  for (int n = 0; n < 300; ++n) {
    const double x = n % 4 == 0 ? ux(rng) : 0.0123 + 1e-3 * ux(rng);
    SplineGrid::Sample direct, cached;
    g.eval(x, 0.0, direct);
    g.eval(x, 0.0, cache, cached);
    EXPECT_EQ(direct.outside, cached.outside);
    for (int c = 0; c < 2; ++c) {
      EXPECT_NEAR(cached.f[c], direct.f[c], 1e-13 * (1 + std::abs(direct.f[c]))) << x;
      EXPECT_NEAR(cached.grad[c][0], direct.grad[c][0], 1e-11 * (1 + std::abs(direct.grad[c][0]))) << x;
      EXPECT_NEAR(cached.hess[c][0], direct.hess[c][0], 1e-9 * (1 + std::abs(direct.hess[c][0]))) << x;
      EXPECT_EQ(cached.grad[c][1], 0.0);
      EXPECT_EQ(cached.hess[c][2], 0.0);
    }
    // The Dual along x: its derivative is the value's slope.
    SplineGrid::SampleT<ad::DualN<2>> dual;
    g.eval(ad::seeded<2>(x, 0), 0.0, cache, dual);
    for (int c = 0; c < 2; ++c) {
      EXPECT_NEAR(dual.f[c].der[0], direct.grad[c][0], 1e-11 * (1 + std::abs(direct.grad[c][0]))) << x;
      EXPECT_NEAR(dual.grad[c][0].der[0], direct.outside ? 0.0 : direct.hess[c][0], 1e-9 * (1 + std::abs(direct.hess[c][0])));
    }
  }
}

TEST(SplineGrid, CurveEvaluationIsTheOneCoordinateSpline) {
  // One coordinate, two grids on one axis sharing a lookup (the planar car's
  // tables over the rack travel): against the function the samples come
  // from (value O(h^4), slope O(h^3) well inside: the natural ends' error
  // decays by 2 - sqrt(3) a node), the general evaluation (the
  // same sums), and a grid on another axis refused the shared lookup.
  const GridAxis ax{-0.06, 0.004, 31};
  std::vector<std::vector<double>> a(2, std::vector<double>(ax.nodes)), b(1, std::vector<double>(ax.nodes));
  for (int i = 0; i < ax.nodes; ++i) {
    const double x = ax.start + i * ax.step;
    a[0][i] = std::sin(20 * x);
    a[1][i] = std::exp(5 * x);
    b[0][i] = x * x * x;
  }
  const SplineGrid ga(ax, GridAxis{0, 1, 1}, a), gb(ax, GridAxis{0, 1, 1}, b);
  const SplineGrid other(GridAxis{-0.06, 0.005, 25}, GridAxis{0, 1, 1}, std::vector<std::vector<double>>(1, std::vector<double>(25, 1.0)));
  EXPECT_TRUE(ga.sameAxisX(gb));
  EXPECT_FALSE(ga.sameAxisX(other));
  for (double x : {-0.071, -0.06, -0.0413, -0.0213, 0.0, 0.0177, 0.06, 0.08}) {
    const SplineGrid::CurvePoint at = ga.curvePoint(x);
    SplineGrid::Curve ca, cb;
    SplineGrid::Sample sa, sb;
    ga.evalCurve(at, ca);
    gb.evalCurve(at, cb);
    ga.eval(x, 0.0, sa);
    gb.eval(x, 0.0, sb);
    EXPECT_EQ(ca.outside, x < ax.start || x > ax.end());
    for (int c = 0; c < 2; ++c) {
      EXPECT_DOUBLE_EQ(ca.f[c], sa.f[c]) << x;
      EXPECT_DOUBLE_EQ(ca.df[c], sa.grad[c][0]) << x;
      EXPECT_DOUBLE_EQ(ca.ddf[c], sa.hess[c][0]) << x;
    }
    EXPECT_DOUBLE_EQ(cb.f[0], sb.f[0]) << x;
    EXPECT_DOUBLE_EQ(cb.df[0], sb.grad[0][0]) << x;
    if (std::abs(x) < 0.025) {  // 8 nodes and more from either end
      EXPECT_NEAR(ca.f[0], std::sin(20 * x), 1e-6) << x;
      EXPECT_NEAR(ca.df[0], 20 * std::cos(20 * x), 1e-3) << x;
      EXPECT_NEAR(ca.f[1], std::exp(5 * x), 1e-8) << x;
      EXPECT_NEAR(cb.f[0], x * x * x, 1e-9) << x;
      EXPECT_NEAR(cb.ddf[0], 6 * x, 1e-3) << x;
    }
  }
  SplineGrid::Curve c;
  const SplineGrid two(GridAxis{0, 1, 3}, GridAxis{0, 1, 3}, std::vector<std::vector<double>>(1, std::vector<double>(9, 0.0)));
  EXPECT_THROW(two.evalCurve(two.curvePoint(0.5), c), std::logic_error);
}

TEST(SplineGrid, RefusesBadGrids) {
  const std::vector<std::vector<double>> two(1, std::vector<double>(2, 0.0));
  EXPECT_THROW(SplineGrid(GridAxis{0, 1, 2}, GridAxis{0, 1, 1}, two), std::invalid_argument);
  std::vector<std::vector<double>> nan(1, std::vector<double>(3, 0.0));
  nan[0][1] = std::nan("");
  EXPECT_THROW(SplineGrid(GridAxis{0, 1, 3}, GridAxis{0, 1, 1}, nan), std::invalid_argument);
}

// Body offset from a universal joint's centre (in the child joint frame), the
// spring's anchor on the ground and on the body (body frame).
const Vec3 kOffset(0.12, -0.05, -0.4);
const Vec3 kGroundAnchor(0.3, 0.2, 0.5);
const Vec3 kBodyAnchor(0.05, 0.02, 0.1);

Body pendulumBody() {
  Body b;
  b.name = "bob";
  b.mass = 3.0;
  b.com = Vec3(0.01, 0.02, -0.03);
  b.inertia = Vec3(0.05, 0.07, 0.04).asDiagonal();
  b.parent = kGround;
  b.jointName = "hinge";
  return b;
}

SpringDamper pendulumSpring() {
  SpringDamper s;
  s.name = "spring";
  s.freeLength = 0.9;
  s.spring.coefficient = 800.0;
  s.damper.coefficient = 40.0;
  return s;
}

Model universalPendulum() {
  ModelBuilder mb;
  Body b = pendulumBody();
  b.joint = JointType::Universal;
  b.inChild.origin = -kOffset;  // the body frame sits at kOffset from the joint centre
  const int i = mb.addBody(b);
  SpringDamper s = pendulumSpring();
  s.bodyA = kGround;
  s.pointA = kGroundAnchor;
  s.bodyB = i;
  s.pointB = kBodyAnchor;
  mb.addSpring(s);
  return mb.build();
}

// The same pendulum as a table over (alpha, beta): R = Rx(alpha) Ry(beta)
// (psi = 0, phi = alpha, theta = beta), origin R kOffset, and the spring length.
Model tabulatedPendulum() {
  const GridAxis a{-0.6, 0.02, 61}, b{-0.5, 0.02, 51};
  std::vector<std::vector<double>> samples(7, std::vector<double>(a.nodes * b.nodes));
  for (int j = 0; j < b.nodes; ++j)
    for (int i = 0; i < a.nodes; ++i) {
      const double al = a.start + i * a.step, be = b.start + j * b.step;
      const Mat3 R = rotX(al) * rotY(be);
      const Vec3 o = R * kOffset;
      const int n = i + a.nodes * j;
      for (int k = 0; k < 3; ++k) samples[k][n] = o(k);
      samples[3][n] = 0;
      samples[4][n] = al;
      samples[5][n] = be;
      samples[6][n] = (o + R * kBodyAnchor - kGroundAnchor).norm();
    }
  ModelBuilder mb;
  JointTable t;
  t.grid = SplineGrid(a, b, samples);
  Body body = pendulumBody();
  body.joint = JointType::Tabulated2;
  body.table = mb.addTable(t);
  const int i = mb.addBody(body);
  SpringDamper s = pendulumSpring();
  s.tableBody = i;
  s.tableComponent = 6;
  mb.addSpring(s);
  return mb.build();
}

TEST(TabulatedJoint, MatchesTheJointItTabulates) {
  const Model exact = universalPendulum();
  const Model table = tabulatedPendulum();
  ASSERT_EQ(exact.nv, 2);
  ASSERT_EQ(table.nv, 2);
  MultibodyDae de(exact), dt(table);
  integ::Residual re, rt;
  re.resize(de.sizes());
  rt.resize(dt.sizes());
  integ::Message msg;
  const integ::Vec lambda;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    integ::Vec q(2), v(2), a(2);
    q << 0.4 * U(rng), 0.35 * U(rng);
    v << 3 * U(rng), 3 * U(rng);
    a << 20 * U(rng), 20 * U(rng);
    ASSERT_EQ(de.residual(0, q, v, a, lambda, re, false, msg), integ::EvalStatus::Ok);
    ASSERT_EQ(dt.residual(0, q, v, a, lambda, rt, false, msg), integ::EvalStatus::Ok);
    // Pose, velocity and acceleration of the body, then the generalised forces.
    EXPECT_LT((de.data().p[0] - dt.data().p[0]).norm(), 1e-7);
    EXPECT_LT((de.data().R[0] - dt.data().R[0]).norm(), 1e-7);
    EXPECT_LT((de.data().vel[0] - dt.data().vel[0]).norm(), 1e-5);
    EXPECT_LT((de.data().acc[0] - dt.data().acc[0]).norm(), 1e-4);
    EXPECT_NEAR(de.data().springLength[0], dt.data().springLength[0], 1e-7);
    EXPECT_NEAR(de.data().springForce[0], dt.data().springForce[0], 1e-3);
    EXPECT_LT((re.F - rt.F).norm(), 1e-3 * (1 + re.F.norm())) << re.F.transpose() << " | " << rt.F.transpose();
  }
}

TEST(TabulatedJoint, RefusesATableOfTheWrongDimension) {
  ModelBuilder mb;
  JointTable t;
  std::vector<std::vector<double>> samples(6, std::vector<double>(5, 0.0));
  t.grid = SplineGrid(GridAxis{0, 0.1, 5}, GridAxis{0, 1, 1}, samples);
  Body b = pendulumBody();
  b.joint = JointType::Tabulated2;
  b.table = mb.addTable(t);
  EXPECT_THROW(mb.addBody(b), ModelError);
}

}  // namespace
}  // namespace bdfcar::mb
