// Jacobian blocks of the DAE residual: analytic when the DAE provides them,
// forward finite differences otherwise (F_q along the retraction, F_v, F_a).
#pragma once

#include "integrator/dae.h"

namespace bdfcar::integ {

struct BlockWorkspace {
  Residual r0, r1;
  Vec q, v, a, dq, lambdaZero;
  Message msg;
  void resize(const DaeSizes& s);
};

// F_a = dF/da (the joint-space mass matrix).
EvalStatus massMatrixBlock(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                           Mat& Fa, BlockWorkspace& ws, long& residualCount);
// Phi_q.
EvalStatus constraintJacobianBlock(Dae& dae, double t, const Vec& q, Mat& Phi_q, BlockWorkspace& ws,
                                   long& residualCount);
// F_q and F_v by forward differences of F (2 nv residual evaluations).
EvalStatus stiffnessDampingBlocks(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                                  Mat& Fq, Mat& Fv, BlockWorkspace& ws, long& residualCount);

}  // namespace bdfcar::integ
