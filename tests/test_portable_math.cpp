// The physics' own arithmetic (physics/portable_math.h, physics/autodiff.h)
// against independent references: sin and cos against the C library's long
// double ones, a dual number's derivatives against hand-derived ones, a
// narrow one's lifted derivatives against the wide one's.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "autodiff.h"
#include "portable_math.h"

namespace bdfcar {
namespace {

// |a - b| in units in the last place of b (a double).
double ulps(double a, long double b) {
  const double db = static_cast<double>(b);
  const double ulp = std::nextafter(std::abs(db), std::numeric_limits<double>::infinity()) - std::abs(db);
  return static_cast<double>(std::abs(static_cast<long double>(a) - b) / ulp);
}

TEST(PortableMath, SinCosWithinTwoUlpsOfTheLongDoubleOnes) {
  // The series within pi/4 (dense), SLEEF beyond; both sides of the switch.
  double worst = 0, worstAt = 0;
  auto check = [&](double x) {
    const pm::SinCos r = pm::sincos(x);
    const double e = std::max(x == 0 ? 0.0 : ulps(r.s, sinl(x)), ulps(r.c, cosl(x)));
    if (e > worst) worst = e, worstAt = x;
  };
  const double quarter = 0.78539816339744828;
  for (int i = -200000; i <= 200000; ++i) check(quarter * i / 200000.0);
  for (int i = 1; i <= 1000; ++i) {
    check(std::nextafter(quarter, 0.0) - i * 1e-15);
    check(std::nextafter(quarter, 1.0) + i * 1e-15);
    check(-quarter - i * 1e-12);
  }
  for (int i = -10000; i <= 10000; ++i) check(i * 1e-3);  // far angles: a yaw, a wheel's spin
  EXPECT_LT(worst, 2.0) << "at " << worstAt;
  // Small angles keep their relative accuracy (a table's toe of 1e-9 rad).
  for (double x : {1e-300, 1e-30, 1e-9, -2e-9}) EXPECT_EQ(pm::sincos(x).s, x);
}

TEST(PortableMath, DualNumbersCarryTheDerivativesOfTheirFunctions) {
  // f(x, y) = sin(x) y / (1 + x^2) + exp(-y) sqrt(x) - atan2(y, x) + tanh(x y) at (0.7, 1.3),
  // its gradient by hand.
  const double x = 0.7, y = 1.3;
  const ad::Dual X = ad::seeded(x, 0), Y = ad::seeded(y, 1);
  const ad::Dual f = pm::sin(X) * Y / (1.0 + X * X) + pm::exp(-Y) * sqrt(X) - pm::atan2(Y, X) + pm::tanh(X * Y);
  const double d = 1 + x * x, th = std::tanh(x * y), r2 = x * x + y * y;
  const double fx = std::cos(x) * y / d - std::sin(x) * y * 2 * x / (d * d) + std::exp(-y) * 0.5 / std::sqrt(x) +
                    y / r2 + (1 - th * th) * y;
  const double fy = std::sin(x) / d - std::exp(-y) * std::sqrt(x) - x / r2 + (1 - th * th) * x;
  EXPECT_NEAR(f.der[0], fx, 1e-14);
  EXPECT_NEAR(f.der[1], fy, 1e-14);
  for (int k = 2; k < ad::kDirections; ++k) EXPECT_EQ(f.der[k], 0.0);
  // min, max and clamp keep the chosen argument's derivatives; sqrt0 and
  // norm0 have a zero derivative at zero where sqrt's is 0/0.
  EXPECT_EQ(ad::min(X, 0.5).der[0], 0.0);
  EXPECT_EQ(ad::max(X, 0.5).der[0], 1.0);
  EXPECT_EQ(ad::clamp(Y, 0.0, 1.0).der[1], 0.0);
  const ad::Dual zero = ad::seeded(0.0, 3);
  EXPECT_EQ(ad::sqrt0(zero * zero).der[3], 0.0);
  EXPECT_TRUE(std::isnan(sqrt(zero * zero).der[3]));
  const Eigen::Matrix<ad::Dual, 3, 1> v(zero, zero, zero);
  EXPECT_EQ(ad::norm0(v).der[3], 0.0);
}

TEST(PortableMath, ANarrowDualLiftedCarriesTheWideOnesDerivatives) {
  // g(x, y) on two directions, lifted onto the 16 that x and y carry (each a
  // function of the wide directions), against g evaluated on the wide Dual
  // directly: the chain rule by ad::lift is the derivative the wide
  // evaluation takes operation by operation.
  ad::Dual X(0.7), Y(1.3);
  for (int k = 0; k < ad::kDirections; ++k) {
    X.der[k] = 0.1 * k - 0.4;
    Y.der[k] = k % 3 == 0 ? 0.0 : 1.0 / (1 + k);
  }
  auto g = [](const auto& x, const auto& y) {
    return pm::sin(x) * y / (1.0 + x * x) + pm::exp(-y) * sqrt(x) - pm::atan2(y, x) + pm::tanh(x * y);
  };
  const ad::Dual wide = g(X, Y);
  const ad::DualN<2> narrow = g(ad::seeded<2>(X.val, 0), ad::seeded<2>(Y.val, 1));
  const ad::Dual lifted = ad::lift(narrow, std::array<const ad::Dual*, 2>{&X, &Y});
  EXPECT_EQ(lifted.val, wide.val);
  for (int k = 0; k < ad::kDirections; ++k)
    EXPECT_NEAR(lifted.der[k], wide.der[k], 1e-14 * (1 + std::abs(wide.der[k]))) << "direction " << k;
  // A direction neither input carries stays exactly zero.
  ad::Dual Z = ad::seeded(0.3, 5);
  const ad::Dual none = ad::lift(ad::seeded<2>(2.0, 0) * 3.0, std::array<const ad::Dual*, 2>{&Z, &Z});
  for (int k = 0; k < ad::kDirections; ++k) EXPECT_EQ(none.der[k], k == 5 ? 3.0 : 0.0);
}

}  // namespace
}  // namespace bdfcar
