// Forward-mode automatic differentiation for the closed forms' Jacobians
// (issue 25): a number carrying its value and its derivatives along
// kDirections directions. Code written for a scalar type T runs with
// T = double on the step's path and T = ad::Dual for the Jacobian: one
// source of the physics, its derivatives exact (not differences).
//
// Its own small type rather than Eigen's AutoDiffScalar (unsupported/): the
// latter's derivatives are expression templates, and in Eigen's matrix
// expressions over them every intermediate became a copy of the whole
// derivative vector. The kinematic rung's Jacobian took 490k instructions
// with it (more than its 29 finite-difference residuals, 350k); with plain
// eager operations on a fixed array, each arithmetic operation is a few
// vector instructions over the 16 derivatives. It is an Eigen scalar
// (NumTraits below), so the closed forms' vector algebra runs on it as is.
//
// The transcendental functions keep portable_math.h's promise: the value
// and the derivative both from SLEEF (pm::), the same bits on every machine
// of a build flavour; sqrt is IEEE-exact, a quotient's value a times 1 / b
// (within an ulp or two of a / b: only Jacobians are computed in Duals, never
// the residual the step converges on). sqrt0 and norm0
// give a zero derivative where the argument is zero (a straight run's
// lateral slip, a car at rest: the plain square root's derivative there is
// 0/0).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "portable_math.h"

namespace bdfcar::ad {

inline constexpr int kDirections = 16;

struct Dual {
  double val = 0.0;
  std::array<double, kDirections> der{};  // d val / d direction k
  Dual() = default;
  Dual(double x) : val(x) {}  // NOLINT: a constant converts implicitly (as a double to a double)
  double value() const { return val; }

  Dual& operator+=(const Dual& b) {
    val += b.val;
    for (int k = 0; k < kDirections; ++k) der[k] += b.der[k];
    return *this;
  }
  Dual& operator-=(const Dual& b) {
    val -= b.val;
    for (int k = 0; k < kDirections; ++k) der[k] -= b.der[k];
    return *this;
  }
  Dual& operator*=(const Dual& b) {
    for (int k = 0; k < kDirections; ++k) der[k] = der[k] * b.val + val * b.der[k];
    val *= b.val;
    return *this;
  }
  Dual& operator/=(const Dual& b) {
    const double inv = 1.0 / b.val, q = val * inv;
    for (int k = 0; k < kDirections; ++k) der[k] = (der[k] - q * b.der[k]) * inv;
    val = q;
    return *this;
  }
  Dual& operator+=(double b) {
    val += b;
    return *this;
  }
  Dual& operator-=(double b) {
    val -= b;
    return *this;
  }
  Dual& operator*=(double b) {
    val *= b;
    for (double& d : der) d *= b;
    return *this;
  }
  Dual& operator/=(double b) {
    val /= b;
    for (double& d : der) d /= b;
    return *this;
  }
};

// The chain rule through f at x: value fx, slope dfdx.
inline Dual chain(const Dual& x, double fx, double dfdx) {
  Dual r(fx);
  for (int k = 0; k < kDirections; ++k) r.der[k] = dfdx * x.der[k];
  return r;
}

// Binary operations build their result afresh (no operand can alias it:
// the loops vectorise without overlap checks).
inline Dual operator-(const Dual& a) { return chain(a, -a.val, -1.0); }
inline Dual operator+(const Dual& a, const Dual& b) {
  Dual r(a.val + b.val);
  for (int k = 0; k < kDirections; ++k) r.der[k] = a.der[k] + b.der[k];
  return r;
}
inline Dual operator-(const Dual& a, const Dual& b) {
  Dual r(a.val - b.val);
  for (int k = 0; k < kDirections; ++k) r.der[k] = a.der[k] - b.der[k];
  return r;
}
inline Dual operator*(const Dual& a, const Dual& b) {
  Dual r(a.val * b.val);
  for (int k = 0; k < kDirections; ++k) r.der[k] = a.der[k] * b.val + a.val * b.der[k];
  return r;
}
inline Dual operator/(const Dual& a, const Dual& b) {
  const double inv = 1.0 / b.val;
  Dual r(a.val * inv);
  for (int k = 0; k < kDirections; ++k) r.der[k] = (a.der[k] - r.val * b.der[k]) * inv;
  return r;
}
inline Dual operator+(const Dual& a, double b) {
  Dual r = a;
  r.val += b;
  return r;
}
inline Dual operator-(const Dual& a, double b) {
  Dual r = a;
  r.val -= b;
  return r;
}
inline Dual operator*(const Dual& a, double b) { return chain(a, a.val * b, b); }
inline Dual operator/(const Dual& a, double b) {
  Dual r(a.val / b);
  for (int k = 0; k < kDirections; ++k) r.der[k] = a.der[k] / b;
  return r;
}
inline Dual operator+(double a, const Dual& b) { return b + a; }
inline Dual operator-(double a, const Dual& b) { return chain(b, a - b.val, -1.0); }
inline Dual operator*(double a, const Dual& b) { return chain(b, a * b.val, a); }
inline Dual operator/(double a, const Dual& b) {
  const double q = a / b.val;
  return chain(b, q, -q / b.val);
}

// Comparisons by value (the branches of the force laws).
#define BDFCAR_DUAL_COMPARISON(op)                                             \
  inline bool operator op(const Dual& a, const Dual& b) { return a.val op b.val; } \
  inline bool operator op(const Dual& a, double b) { return a.val op b; }         \
  inline bool operator op(double a, const Dual& b) { return a op b.val; }
BDFCAR_DUAL_COMPARISON(<)
BDFCAR_DUAL_COMPARISON(>)
BDFCAR_DUAL_COMPARISON(<=)
BDFCAR_DUAL_COMPARISON(>=)
BDFCAR_DUAL_COMPARISON(==)
BDFCAR_DUAL_COMPARISON(!=)
#undef BDFCAR_DUAL_COMPARISON

// Found by argument-dependent lookup from code written for T (`using
// std::sqrt; sqrt(x)`) and from Eigen's norms.
inline Dual sqrt(const Dual& x) {
  const double r = std::sqrt(x.val);
  return chain(x, r, 0.5 / r);
}
inline Dual abs(const Dual& x) { return x.val < 0 ? -x : x; }
inline Dual abs2(const Dual& x) { return x * x; }
inline Dual pow(const Dual& x, double e) {
  const double p = std::pow(x.val, e);
  return chain(x, p, e * std::pow(x.val, e - 1.0));
}

template <typename T>
inline constexpr bool isDual = std::is_same_v<std::remove_cvref_t<T>, Dual>;

// The value of a double or a Dual.
inline double value(double x) { return x; }
inline double value(const Dual& x) { return x.val; }
// x with direction k seeded: x + e_k.
inline Dual seeded(double x, int k) {
  Dual d(x);
  d.der[k] = 1.0;
  return d;
}

// The sign of the value (+1, -1, 0): a constant.
template <typename T>
inline double sign(const T& x) {
  const double v = value(x);
  return (v > 0) - (v < 0);
}

// The type of an expression of a and b: Dual if either is.
template <typename A, typename B>
using Common = std::conditional_t<isDual<A> || isDual<B>, Dual, double>;

// min, max and clamp by value, choosing as std::min, std::max and
// std::clamp do (the same argument on a tie); the chosen one keeps its
// derivatives, a double bound has none.
template <typename A, typename B>
inline Common<A, B> min(const A& a, const B& b) {
  using R = Common<A, B>;
  return value(b) < value(a) ? R(b) : R(a);
}
template <typename A, typename B>
inline Common<A, B> max(const A& a, const B& b) {
  using R = Common<A, B>;
  return value(a) < value(b) ? R(b) : R(a);
}
template <typename X, typename L, typename H>
inline Common<X, Common<L, H>> clamp(const X& x, const L& lo, const H& hi) {
  using R = Common<X, Common<L, H>>;
  return value(x) < value(lo) ? R(lo) : (value(hi) < value(x) ? R(hi) : R(x));
}

// sqrt with a zero derivative at zero.
inline double sqrt0(double x) { return std::sqrt(x); }
inline Dual sqrt0(const Dual& x) {
  const double r = std::sqrt(x.val);
  return r > 0 ? chain(x, r, 0.5 / r) : Dual(r);
}
// hypot: std::hypot's bits for doubles, sqrt0 of the sum of squares for Duals.
inline double hypot(double a, double b) { return std::hypot(a, b); }
inline Dual hypot(const Dual& a, const Dual& b) { return sqrt0(a * a + b * b); }
// A vector's norm with a zero derivative at the zero vector.
template <typename Derived>
inline typename Derived::Scalar norm0(const Eigen::MatrixBase<Derived>& v) {
  return sqrt0(v.squaredNorm());
}

}  // namespace bdfcar::ad

// Dual as an Eigen scalar, and its products with doubles.
namespace Eigen {
template <>
struct NumTraits<bdfcar::ad::Dual> : NumTraits<double> {
  using Real = bdfcar::ad::Dual;
  using NonInteger = bdfcar::ad::Dual;
  using Nested = bdfcar::ad::Dual;
  using Literal = bdfcar::ad::Dual;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = bdfcar::ad::kDirections + 1,
    AddCost = bdfcar::ad::kDirections + 1,
    MulCost = 2 * bdfcar::ad::kDirections + 1
  };
};
template <typename BinaryOp>
struct ScalarBinaryOpTraits<bdfcar::ad::Dual, double, BinaryOp> {
  using ReturnType = bdfcar::ad::Dual;
};
template <typename BinaryOp>
struct ScalarBinaryOpTraits<double, bdfcar::ad::Dual, BinaryOp> {
  using ReturnType = bdfcar::ad::Dual;
};
}  // namespace Eigen

// SLEEF's functions of a Dual: the chain rule with SLEEF's derivatives.
namespace bdfcar::pm {

inline ad::Dual sin(const ad::Dual& x) {
  const SinCos r = sincos(x.val);
  return ad::chain(x, r.s, r.c);
}
inline ad::Dual cos(const ad::Dual& x) {
  const SinCos r = sincos(x.val);
  return ad::chain(x, r.c, -r.s);
}
struct DualSinCos {
  ad::Dual s, c;
};
inline DualSinCos sincos(const ad::Dual& x) {
  const SinCos r = sincos(x.val);
  return {ad::chain(x, r.s, r.c), ad::chain(x, r.c, -r.s)};
}
inline ad::Dual tan(const ad::Dual& x) {
  const double t = tan(x.val);
  return ad::chain(x, t, 1.0 + t * t);
}
inline ad::Dual atan(const ad::Dual& x) { return ad::chain(x, atan(x.val), 1.0 / (1.0 + x.val * x.val)); }
inline ad::Dual atan2(const ad::Dual& y, const ad::Dual& x) {
  const double a = y.val, b = x.val, r2 = a * a + b * b;
  ad::Dual r(atan2(a, b));
  for (int k = 0; k < ad::kDirections; ++k) r.der[k] = (b * y.der[k] - a * x.der[k]) / r2;
  return r;
}
inline ad::Dual tanh(const ad::Dual& x) {
  const double t = tanh(x.val);
  return ad::chain(x, t, 1.0 - t * t);
}
inline ad::Dual exp(const ad::Dual& x) {
  const double e = exp(x.val);
  return ad::chain(x, e, e);
}

}  // namespace bdfcar::pm
