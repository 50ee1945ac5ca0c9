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
// Derivatives of the residual (Dae::stateJacobian where the DAE has it and
// no constraints, else by forward differences: 2 nv residual evaluations):
// F_q, F_v, and the constraint-level terms that linearise the
// velocity and acceleration constraints in eqs. 3.12 and 3.14:
// (Phi_q v + Phi_t)_q, g_q and g_v with g = Phi_q a + (Phi_q v)_q v + Phi_tt.
struct StateDerivatives {
  Mat Fq, Fv;                       // (nv x nv)
  Mat phiDotQ, phiDDotQ, phiDDotV;  // (nc x nv)
  void resize(const DaeSizes& s);
};
// fastParts: when given, Dae::fastColumnParts at the point (from the
// residual the differences are taken against).
EvalStatus stateDerivativeBlocks(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                                 StateDerivatives& out, BlockWorkspace& ws, long& residualCount,
                                 Mat* fastParts = nullptr);
// Columns [begin, end) of those blocks alone (of F_q, the constraint-level
// terms and F_v: 2 (end - begin) + 1 residuals, always by differences), the
// rest of `out` kept: a Jacobian taken in slices over several steps.
EvalStatus stateDerivativeColumns(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                                  int begin, int end, StateDerivatives& out, BlockWorkspace& ws, long& residualCount,
                                  Mat* fastParts = nullptr);
// The F_v (and g_v) columns of the DAE's fast coordinates alone
// (Dae::fastColumns(): one residual per column, differenced against `base`,
// the residual at the point), the rest of `out` kept.
EvalStatus fastVelocityColumns(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                               const Residual& base, StateDerivatives& out, BlockWorkspace& ws, long& residualCount);

}  // namespace bdfcar::integ
