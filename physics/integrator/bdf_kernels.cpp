#include "integrator/bdf_kernels.h"

#include <array>
#include <cmath>
#include <utility>

namespace bdfcar::integ::kernels {

namespace {

// The loops' trip count: N when fixed, n otherwise.
template <int N>
constexpr int count(int n) {
  return N == Eigen::Dynamic ? n : N;
}

// Outputs never alias inputs or each other (the integrator's own vectors):
// said by __restrict parameters (GCC takes it from parameters, not from
// locals), so that the loops vectorise without run-time overlap checks.
template <int N>
inline void addScaled(int m, double* __restrict y, double x, const double* __restrict v) {
  for (int j = 0; j < count<N>(m); ++j) y[j] += x * v[j];
}

template <int N>
inline void set(int m, double* __restrict y, double x) {
  for (int j = 0; j < count<N>(m); ++j) y[j] = x;
}

template <int N>
inline void copy(int m, double* __restrict y, const double* __restrict x) {
  for (int j = 0; j < count<N>(m); ++j) y[j] = x[j];
}

template <int N>
void predict(int n, const History& h, const Prediction& o) {
  for (double* y : {o.xiQ, o.xiV, o.dPred, o.vPred, o.aPred}) set<N>(n, y, 0.0);
  for (int i = 1; i <= h.k; ++i) {
    if (i > 1) addScaled<N>(n, o.xiQ, h.xi[i], h.delta[i - 1]);
    addScaled<N>(n, o.xiV, h.xi[i], h.v[i - 1]);
  }
  for (int i = 0; i < h.np; ++i) {
    if (i > 0) addScaled<N>(n, o.dPred, h.w[i], h.delta[i]);
    addScaled<N>(n, o.vPred, h.w[i], h.v[i]);
    addScaled<N>(n, o.aPred, h.w[i], h.a[i]);
  }
  copy<N>(n, o.d, o.dPred);
  copy<N>(n, o.v, o.vPred);
  copy<N>(n, o.a, o.aPred);
}

template <int N>
inline void bdfResiduals(int m, double hp, const double* __restrict d, const double* __restrict v,
                         const double* __restrict a, const double* __restrict rate, const double* __restrict xiQ,
                         const double* __restrict xiV, const double* __restrict F, double* __restrict rhoQ,
                         double* __restrict rhoV, double* __restrict tmp, double* __restrict rhs) {
  const double hp2 = -(hp * hp);
  for (int i = 0; i < count<N>(m); ++i) {
    rhoQ[i] = d[i] - xiQ[i] - hp * rate[i];
    rhoV[i] = v[i] - xiV[i] - hp * a[i];
    tmp[i] = rhoQ[i] + hp * rhoV[i];
    rhs[i] = hp2 * F[i];
  }
}

// y += alpha A x, A m x m column-major. Fixed: column by column, each an
// unrolled vector multiply-add (a 9 x 9 product about 80 instructions,
// against about 210 in Eigen's general kernel, which fixed-size products of
// this size still call). Dynamic: Eigen's kernel (the linkage's sizes,
// where it is the faster).
template <int N>
inline void addProduct(int m, double* __restrict y, double alpha, const double* __restrict A,
                       const double* __restrict x) {
  if constexpr (N == Eigen::Dynamic) {
    Eigen::Map<Eigen::VectorXd>(y, m).noalias() +=
        alpha * (Eigen::Map<const Eigen::MatrixXd>(A, m, m) * Eigen::Map<const Eigen::VectorXd>(x, m));
  } else {
    for (int j = 0; j < N; ++j) {
      const double s = alpha * x[j];
      for (int i = 0; i < N; ++i) y[i] += A[i + j * N] * s;
    }
  }
}

template <int N>
void residuals(int n, double hp, const Iterate& in, const Residuals& out) {
  bdfResiduals<N>(n, hp, in.d, in.v, in.a, in.rate, in.xiQ, in.xiV, in.F, out.rhoQ, out.rhoV, out.tmp, out.rhs);
  addProduct<N>(n, out.rhs, -hp, in.Fv, out.rhoQ);
  addProduct<N>(n, out.rhs, -1.0, in.Fa, out.tmp);
}

template <int N>
void product(int n, const double* A, const double* b, double* x) {
  if constexpr (N == Eigen::Dynamic) {
    Eigen::Map<Eigen::VectorXd>(x, n).noalias() =
        Eigen::Map<const Eigen::MatrixXd>(A, n, n) * Eigen::Map<const Eigen::VectorXd>(b, n);
  } else {
    set<N>(n, x, 0.0);
    addProduct<N>(n, x, 1.0, A, b);
  }
}

template <int N>
void scaledSum(int n, double c, const double* __restrict x, const double* __restrict y, double* __restrict out) {
  for (int i = 0; i < count<N>(n); ++i) out[i] = c * (x[i] + y[i]);
}

template <int N>
inline double applyUpdate(int m, double* __restrict d, double* __restrict v, double* __restrict a,
                          const double* __restrict dq, const double* __restrict dv, const double* __restrict da,
                          double atol, double rtol, double hPrime, double& nonFinite) {
  double s = 0, bad = 0;
  for (int i = 0; i < count<N>(m); ++i) {
    d[i] += dq[i];
    v[i] += dv[i];
    a[i] += da[i];
    bad += (d[i] - d[i]) + (v[i] - v[i]) + (a[i] - a[i]);
    const double w = 1.0 / (atol + rtol * std::abs(d[i]));
    const double x = dq[i] * w, y = hPrime * dv[i] * w;
    s += x * x + y * y;
  }
  nonFinite += bad;
  return s;
}

template <int N>
double update(int n, const Update& u, double& nonFinite) {
  return applyUpdate<N>(n, u.d, u.v, u.a, u.dq, u.dv, u.da, u.atol, u.rtol, u.hPrime, nonFinite);
}

template <int N>
constexpr StepKernels kernelsFor() {
  return {&predict<N>, &residuals<N>, &product<N>, &scaledSum<N>, &update<N>};
}

template <int... Ns>
constexpr std::array<StepKernels, sizeof...(Ns)> fixedKernels(std::integer_sequence<int, Ns...>) {
  return {kernelsFor<Ns + 1>()...};
}

constexpr int kLargestFixed = 16;
constexpr auto kFixed = fixedKernels(std::make_integer_sequence<int, kLargestFixed>{});
constexpr StepKernels kDynamic = kernelsFor<Eigen::Dynamic>();

}  // namespace

const StepKernels& stepKernels(int nv, int nc) {
  if (nc == 0 && nv >= 1 && nv <= kLargestFixed) return kFixed[nv - 1];
  return kDynamic;
}

}  // namespace bdfcar::integ::kernels
