// Backward differentiation formulas on arbitrary node times: the derivative
// of the interpolating polynomial at the newest node, written as
// y_n = xi + h' y'_n with h' = 1/alpha_0 (paper eq. 3.4: h' = h / b0), and
// the extrapolating predictor.
#pragma once

#include <array>

namespace bdfcar::integ {

constexpr int kMaxBdfOrder = 5;

struct BdfCoefficients {
  int order = 1;
  double hPrime = 0;                          // h' = 1 / alpha_0
  std::array<double, kMaxBdfOrder + 1> xi{};  // y_n = sum_{i>=1} xi[i] y_{n-i} + h' y'_n; xi[0] unused
};

// times[0] = t_n (new), times[1..order] = past nodes, strictly decreasing.
BdfCoefficients bdfCoefficients(const double* times, int order);

// Lagrange weights w[i] so that y(t) ~ sum_i w[i] y(nodes[i]), over n nodes.
void lagrangeWeights(const double* nodes, int n, double t, double* w);

}  // namespace bdfcar::integ
