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
// The width is a template parameter: a part of the equations that reads
// only a few of the state's directions (a kinematic corner: its travel and
// travel rate) runs on a narrow DualN and its results are lifted onto the
// wide directions by the chain rule (ad::lift), instead of carrying 16
// derivatives of which 14 are zero through every operation.
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

template <int N>
struct DualN {
  static constexpr int kWidth = N;
  double val = 0.0;
  std::array<double, N> der{};  // d val / d direction k
  DualN() = default;
  DualN(double x) : val(x) {}  // NOLINT: a constant converts implicitly (as a double to a double)
  double value() const { return val; }

  DualN& operator+=(const DualN& b) {
    val += b.val;
    for (int k = 0; k < N; ++k) der[k] += b.der[k];
    return *this;
  }
  DualN& operator-=(const DualN& b) {
    val -= b.val;
    for (int k = 0; k < N; ++k) der[k] -= b.der[k];
    return *this;
  }
  DualN& operator*=(const DualN& b) {
    for (int k = 0; k < N; ++k) der[k] = der[k] * b.val + val * b.der[k];
    val *= b.val;
    return *this;
  }
  DualN& operator/=(const DualN& b) {
    const double inv = 1.0 / b.val, q = val * inv;
    for (int k = 0; k < N; ++k) der[k] = (der[k] - q * b.der[k]) * inv;
    val = q;
    return *this;
  }
  DualN& operator+=(double b) {
    val += b;
    return *this;
  }
  DualN& operator-=(double b) {
    val -= b;
    return *this;
  }
  DualN& operator*=(double b) {
    val *= b;
    for (double& d : der) d *= b;
    return *this;
  }
  DualN& operator/=(double b) {
    val /= b;
    for (double& d : der) d /= b;
    return *this;
  }
};

// The Jacobian's number: as many directions as a pass of stateJacobian.
using Dual = DualN<kDirections>;

// The chain rule through f at x: value fx, slope dfdx.
template <int N>
inline DualN<N> chain(const DualN<N>& x, double fx, double dfdx) {
  DualN<N> r(fx);
  for (int k = 0; k < N; ++k) r.der[k] = dfdx * x.der[k];
  return r;
}

// Binary operations build their result afresh (no operand can alias it:
// the loops vectorise without overlap checks).
template <int N>
inline DualN<N> operator-(const DualN<N>& a) {
  return chain(a, -a.val, -1.0);
}
template <int N>
inline DualN<N> operator+(const DualN<N>& a, const DualN<N>& b) {
  DualN<N> r(a.val + b.val);
  for (int k = 0; k < N; ++k) r.der[k] = a.der[k] + b.der[k];
  return r;
}
template <int N>
inline DualN<N> operator-(const DualN<N>& a, const DualN<N>& b) {
  DualN<N> r(a.val - b.val);
  for (int k = 0; k < N; ++k) r.der[k] = a.der[k] - b.der[k];
  return r;
}
template <int N>
inline DualN<N> operator*(const DualN<N>& a, const DualN<N>& b) {
  DualN<N> r(a.val * b.val);
  for (int k = 0; k < N; ++k) r.der[k] = a.der[k] * b.val + a.val * b.der[k];
  return r;
}
template <int N>
inline DualN<N> operator/(const DualN<N>& a, const DualN<N>& b) {
  const double inv = 1.0 / b.val;
  DualN<N> r(a.val * inv);
  for (int k = 0; k < N; ++k) r.der[k] = (a.der[k] - r.val * b.der[k]) * inv;
  return r;
}
template <int N>
inline DualN<N> operator+(const DualN<N>& a, double b) {
  DualN<N> r = a;
  r.val += b;
  return r;
}
template <int N>
inline DualN<N> operator-(const DualN<N>& a, double b) {
  DualN<N> r = a;
  r.val -= b;
  return r;
}
template <int N>
inline DualN<N> operator*(const DualN<N>& a, double b) {
  return chain(a, a.val * b, b);
}
template <int N>
inline DualN<N> operator/(const DualN<N>& a, double b) {
  DualN<N> r(a.val / b);
  for (int k = 0; k < N; ++k) r.der[k] = a.der[k] / b;
  return r;
}
template <int N>
inline DualN<N> operator+(double a, const DualN<N>& b) {
  return b + a;
}
template <int N>
inline DualN<N> operator-(double a, const DualN<N>& b) {
  return chain(b, a - b.val, -1.0);
}
template <int N>
inline DualN<N> operator*(double a, const DualN<N>& b) {
  return chain(b, a * b.val, a);
}
template <int N>
inline DualN<N> operator/(double a, const DualN<N>& b) {
  const double q = a / b.val;
  return chain(b, q, -q / b.val);
}

// Comparisons by value (the branches of the force laws).
#define BDFCAR_DUAL_COMPARISON(op)                                                         \
  template <int N>                                                                         \
  inline bool operator op(const DualN<N>& a, const DualN<N>& b) { return a.val op b.val; } \
  template <int N>                                                                         \
  inline bool operator op(const DualN<N>& a, double b) { return a.val op b; }              \
  template <int N>                                                                         \
  inline bool operator op(double a, const DualN<N>& b) { return a op b.val; }
BDFCAR_DUAL_COMPARISON(<)
BDFCAR_DUAL_COMPARISON(>)
BDFCAR_DUAL_COMPARISON(<=)
BDFCAR_DUAL_COMPARISON(>=)
BDFCAR_DUAL_COMPARISON(==)
BDFCAR_DUAL_COMPARISON(!=)
#undef BDFCAR_DUAL_COMPARISON

// Found by argument-dependent lookup from code written for T (`using
// std::sqrt; sqrt(x)`) and from Eigen's norms.
template <int N>
inline DualN<N> sqrt(const DualN<N>& x) {
  const double r = std::sqrt(x.val);
  return chain(x, r, 0.5 / r);
}
template <int N>
inline DualN<N> abs(const DualN<N>& x) {
  return x.val < 0 ? -x : x;
}
template <int N>
inline DualN<N> abs2(const DualN<N>& x) {
  return x * x;
}
template <int N>
inline DualN<N> pow(const DualN<N>& x, double e) {
  const double p = std::pow(x.val, e);
  return chain(x, p, e * std::pow(x.val, e - 1.0));
}

template <typename T>
struct IsDual : std::false_type {};
template <int N>
struct IsDual<DualN<N>> : std::true_type {};
template <typename T>
inline constexpr bool isDual = IsDual<std::remove_cvref_t<T>>::value;

// The value of a double or a Dual.
inline double value(double x) { return x; }
template <int N>
inline double value(const DualN<N>& x) {
  return x.val;
}
// x with direction k seeded: x + e_k.
template <int N = kDirections>
inline DualN<N> seeded(double x, int k) {
  DualN<N> d(x);
  d.der[k] = 1.0;
  return d;
}

// y = f(x, ...) computed on a narrow DualN<M> whose directions are the
// scalars x_m (seeded one each), onto the wide directions those scalars
// carry: dy/dk = sum_m dy/dx_m dx_m/dk (the chain rule, exact).
template <int M, int N>
inline DualN<N> lift(const DualN<M>& y, const std::array<const DualN<N>*, static_cast<std::size_t>(M)>& x) {
  DualN<N> r(y.val);
  for (int m = 0; m < M; ++m)
    if (y.der[m] != 0.0)
      for (int k = 0; k < N; ++k) r.der[k] += y.der[m] * x[m]->der[k];
  return r;
}

// The sign of the value (+1, -1, 0): a constant.
template <typename T>
inline double sign(const T& x) {
  const double v = value(x);
  return (v > 0) - (v < 0);
}

// The type of an expression of a and b: the Dual if either is one.
template <typename A, typename B>
using Common = std::conditional_t<isDual<A>, std::remove_cvref_t<A>,
                                  std::conditional_t<isDual<B>, std::remove_cvref_t<B>, double>>;

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
template <int N>
inline DualN<N> sqrt0(const DualN<N>& x) {
  const double r = std::sqrt(x.val);
  return r > 0 ? chain(x, r, 0.5 / r) : DualN<N>(r);
}
// hypot: std::hypot's bits for doubles, sqrt0 of the sum of squares for Duals.
inline double hypot(double a, double b) { return std::hypot(a, b); }
template <int N>
inline DualN<N> hypot(const DualN<N>& a, const DualN<N>& b) {
  return sqrt0(a * a + b * b);
}
// A vector's norm with a zero derivative at the zero vector.
template <typename Derived>
inline typename Derived::Scalar norm0(const Eigen::MatrixBase<Derived>& v) {
  return sqrt0(v.squaredNorm());
}

}  // namespace bdfcar::ad

// Dual as an Eigen scalar, and its products with doubles. Its costs are the
// wide Dual's at every width, so that Eigen unrolls (and so orders its sums)
// alike: a narrow DualN's derivatives lifted by ad::lift are the wide one's,
// bit for bit.
namespace Eigen {
template <int N>
struct NumTraits<bdfcar::ad::DualN<N>> : NumTraits<double> {
  using Real = bdfcar::ad::DualN<N>;
  using NonInteger = bdfcar::ad::DualN<N>;
  using Nested = bdfcar::ad::DualN<N>;
  using Literal = bdfcar::ad::DualN<N>;
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
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<bdfcar::ad::DualN<N>, double, BinaryOp> {
  using ReturnType = bdfcar::ad::DualN<N>;
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, bdfcar::ad::DualN<N>, BinaryOp> {
  using ReturnType = bdfcar::ad::DualN<N>;
};
}  // namespace Eigen

// SLEEF's functions of a Dual: the chain rule with SLEEF's derivatives.
namespace bdfcar::pm {

template <int N>
inline ad::DualN<N> sin(const ad::DualN<N>& x) {
  const SinCos r = sincos(x.val);
  return ad::chain(x, r.s, r.c);
}
template <int N>
inline ad::DualN<N> cos(const ad::DualN<N>& x) {
  const SinCos r = sincos(x.val);
  return ad::chain(x, r.c, -r.s);
}
template <int N>
struct DualSinCos {
  ad::DualN<N> s, c;
};
template <int N>
inline DualSinCos<N> sincos(const ad::DualN<N>& x) {
  const SinCos r = sincos(x.val);
  return {ad::chain(x, r.s, r.c), ad::chain(x, r.c, -r.s)};
}
template <int N>
inline ad::DualN<N> tan(const ad::DualN<N>& x) {
  const double t = tan(x.val);
  return ad::chain(x, t, 1.0 + t * t);
}
template <int N>
inline ad::DualN<N> atan(const ad::DualN<N>& x) {
  return ad::chain(x, atan(x.val), 1.0 / (1.0 + x.val * x.val));
}
template <int N>
inline ad::DualN<N> atan2(const ad::DualN<N>& y, const ad::DualN<N>& x) {
  const double a = y.val, b = x.val, r2 = a * a + b * b;
  ad::DualN<N> r(atan2(a, b));
  for (int k = 0; k < N; ++k) r.der[k] = (b * y.der[k] - a * x.der[k]) / r2;
  return r;
}
template <int N>
inline ad::DualN<N> tanh(const ad::DualN<N>& x) {
  const double t = tanh(x.val);
  return ad::chain(x, t, 1.0 - t * t);
}
template <int N>
inline ad::DualN<N> exp(const ad::DualN<N>& x) {
  const double e = exp(x.val);
  return ad::chain(x, e, e);
}

}  // namespace bdfcar::pm
