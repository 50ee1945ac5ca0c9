#include "integrator/bdf_coefficients.h"

namespace bdfcar::integ {

namespace {

// Each written once, for a node count N known at compile time (the
// dispatch below) or, with N = 0, the count n given at run time: the same
// operations in the same order either way, so the same bits; a known count
// unrolls the loops, with no bound or skipped index tested at run time (a
// BDF2 step's coefficients and predictor weights took 267 instructions a
// step on the planar rung, a few percent of its step).
template <int N>
BdfCoefficients coefficientsOn(const double* t, int nRun) {
  const int n = N > 0 ? N : nRun;
  // alpha_i = l_i'(t_0) for the Lagrange basis on t_0..t_k.
  std::array<double, kMaxBdfOrder + 1> alpha{};
  // l_0'(t_0) = sum_{j != 0} 1 / (t_0 - t_j)
  for (int j = 1; j < n; ++j) alpha[0] += 1.0 / (t[0] - t[j]);
  // l_i'(t_0) = prod_{j != i, j != 0} (t_0 - t_j) / prod_{j != i} (t_i - t_j), i >= 1
  for (int i = 1; i < n; ++i) {
    double num = 1.0, den = 1.0;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      den *= t[i] - t[j];
      if (j != 0) num *= t[0] - t[j];
    }
    alpha[i] = num / den;
  }
  BdfCoefficients c;
  c.order = n - 1;
  c.hPrime = 1.0 / alpha[0];
  for (int i = 1; i < n; ++i) c.xi[i] = -alpha[i] / alpha[0];
  return c;
}

template <int N>
void weightsOn(const double* nodes, int nRun, double t, double* w) {
  const int n = N > 0 ? N : nRun;
  for (int i = 0; i < n; ++i) {
    double p = 1.0;
    for (int j = 0; j < n; ++j)
      if (j != i) p *= (t - nodes[j]) / (nodes[i] - nodes[j]);
    w[i] = p;
  }
}

}  // namespace

BdfCoefficients bdfCoefficients(const double* t, int order) {
  switch (order) {
    case 1: return coefficientsOn<2>(t, 2);
    case 2: return coefficientsOn<3>(t, 3);
    case 3: return coefficientsOn<4>(t, 4);
    default: return coefficientsOn<0>(t, order + 1);
  }
}

void lagrangeWeights(const double* nodes, int n, double t, double* w) {
  switch (n) {
    case 2: return weightsOn<2>(nodes, n, t, w);
    case 3: return weightsOn<3>(nodes, n, t, w);
    case 4: return weightsOn<4>(nodes, n, t, w);
    default: return weightsOn<0>(nodes, n, t, w);
  }
}

}  // namespace bdfcar::integ
