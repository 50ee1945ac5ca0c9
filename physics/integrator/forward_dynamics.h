// Accelerations and multipliers from positions and velocities (the index-1
// form): [F_a Phi_q^T; Phi_q 0] [a; lambda] = [-F(q, v, 0, 0); -rhs], with the
// acceleration-level constraint stabilised after Baumgarte:
// Phi'' + 2 alpha Phi' + beta^2 Phi = 0. Used for consistent initial values
// and by the explicit integrators.
#pragma once

#include <Eigen/LU>

#include "integrator/dae_blocks.h"
#include "integrator/step_types.h"

namespace bdfcar::integ {

class ForwardDynamics {
 public:
  explicit ForwardDynamics(Dae& dae);
  EvalStatus solve(double t, const Vec& q, const Vec& v, double alpha, double beta, Vec& a, Vec& lambda,
                   Counters& counters, Message& msg);

 private:
  Dae& dae_;
  DaeSizes n_;
  BlockWorkspace ws_;
  Residual r_;
  Mat M_, J_, A_;
  Vec rhs_, sol_, zeroV_, zeroC_;
  Eigen::PartialPivLU<Mat> lu_;
};

}  // namespace bdfcar::integ
