#include "integrator/bdf_coefficients.h"

namespace bdfcar::integ {

BdfCoefficients bdfCoefficients(const double* t, int order) {
  // alpha_i = l_i'(t_0) for the Lagrange basis on t_0..t_k.
  const int n = order + 1;
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
  c.order = order;
  c.hPrime = 1.0 / alpha[0];
  for (int i = 1; i < n; ++i) c.xi[i] = -alpha[i] / alpha[0];
  return c;
}

void lagrangeWeights(const double* nodes, int n, double t, double* w) {
  for (int i = 0; i < n; ++i) {
    double p = 1.0;
    for (int j = 0; j < n; ++j)
      if (j != i) p *= (t - nodes[j]) / (nodes[i] - nodes[j]);
    w[i] = p;
  }
}

}  // namespace bdfcar::integ
