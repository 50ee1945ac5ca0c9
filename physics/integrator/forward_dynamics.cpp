#include "integrator/forward_dynamics.h"

#include "matrix_blocking.h"

namespace bdfcar::integ {

ForwardDynamics::ForwardDynamics(Dae& dae) : dae_(dae), n_(dae.sizes()), lu_(n_.nv + n_.nc) {
  pinMatrixBlocking();  // before any product: the BDF and explicit integrators each hold one of these
  ws_.resize(n_);
  r_.resize(n_);
  M_.setZero(n_.nv, n_.nv);
  J_.setZero(n_.nc, n_.nv);
  A_.setZero(n_.nv + n_.nc, n_.nv + n_.nc);
  rhs_.setZero(n_.nv + n_.nc);
  sol_.setZero(n_.nv + n_.nc);
  zeroV_.setZero(n_.nv);
  zeroC_.setZero(n_.nc);
}

EvalStatus ForwardDynamics::solve(double t, const Vec& q, const Vec& v, double alpha, double beta, Vec& a,
                                  Vec& lambda, Counters& c, Message& msg) {
  // F is affine in (a, lambda): F = F_a a + Phi_q^T lambda + F(q, v, 0, 0).
  EvalStatus st = dae_.residual(t, q, v, zeroV_, zeroC_, r_, true, msg);
  ++c.residuals;
  if (st != EvalStatus::Ok) return st;
  st = massMatrixBlock(dae_, t, q, v, zeroV_, zeroC_, M_, ws_, c.jacobianResiduals);
  if (st == EvalStatus::Ok) st = constraintJacobianBlock(dae_, t, q, J_, ws_, c.jacobianResiduals);
  if (st != EvalStatus::Ok) {
    msg = ws_.msg;
    return st;
  }
  const int nv = n_.nv, nc = n_.nc;
  A_.topLeftCorner(nv, nv) = M_;
  A_.topRightCorner(nv, nc) = J_.transpose();
  A_.bottomLeftCorner(nc, nv) = J_;
  A_.bottomRightCorner(nc, nc).setZero();
  rhs_.head(nv) = -r_.F;
  rhs_.tail(nc) = -(r_.phiDDot + 2.0 * alpha * r_.phiDot + beta * beta * r_.phi);
  lu_.compute(A_);
  ++c.factorizations;
  sol_.noalias() = lu_.solve(rhs_);
  ++c.solves;
  if (!sol_.allFinite()) {
    msg.set("forward dynamics: singular mass/constraint matrix at t = %.6g s", t);
    return EvalStatus::Fatal;
  }
  a = sol_.head(nv);
  lambda = sol_.tail(nc);
  return EvalStatus::Ok;
}

}  // namespace bdfcar::integ
