// Whether every entry of a vector is finite, in one pass without a branch
// per entry: x - x is 0 for a finite x and NaN for an infinite or NaN one, so
// their sum is 0 exactly when all are finite (Eigen's allFinite() branches on
// each entry; the step asks this of its state and residual every time).
#pragma once

#include <Eigen/Core>

namespace bdfcar::integ {

inline bool allFinite(const Eigen::VectorXd& x) {
  const double* p = x.data();
  double sum = 0.0;
  for (Eigen::Index i = 0, n = x.size(); i < n; ++i) sum += p[i] - p[i];
  return sum == 0.0;
}

}  // namespace bdfcar::integ
