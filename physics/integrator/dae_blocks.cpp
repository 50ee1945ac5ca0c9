#include "integrator/dae_blocks.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::integ {

namespace {
int constraintRows(const StateDerivatives& d) { return static_cast<int>(d.phiDotQ.rows()); }
// Forward-difference increments: sqrt(machine epsilon) on unit-scale
// coordinates (m, rad); velocities scale with their own magnitude.
constexpr double kFdStep = 1.5e-8;
double velocityIncrement(double v) { return kFdStep * std::max(1.0, std::abs(v)); }
}  // namespace

void BlockWorkspace::resize(const DaeSizes& s) {
  r0.resize(s);
  r1.resize(s);
  q.setZero(s.nq);
  v.setZero(s.nv);
  a.setZero(s.nv);
  dq.setZero(s.nv);
  lambdaZero.setZero(s.nc);
}

EvalStatus massMatrixBlock(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                           Mat& Fa, BlockWorkspace& ws, long& count) {
  if (dae.massMatrix(t, q, Fa)) return EvalStatus::Ok;
  EvalStatus st = dae.residual(t, q, v, a, lambda, ws.r0, false, ws.msg);
  ++count;
  if (st != EvalStatus::Ok) return st;
  ws.a = a;
  for (int i = 0; i < a.size(); ++i) {
    const double h = velocityIncrement(a(i));
    ws.a(i) = a(i) + h;
    st = dae.residual(t, q, v, ws.a, lambda, ws.r1, false, ws.msg);
    ++count;
    if (st != EvalStatus::Ok) return st;
    Fa.col(i) = (ws.r1.F - ws.r0.F) / h;
    ws.a(i) = a(i);
  }
  return EvalStatus::Ok;
}

EvalStatus constraintJacobianBlock(Dae& dae, double t, const Vec& q, Mat& J, BlockWorkspace& ws, long& count) {
  if (dae.constraintJacobian(t, q, J)) return EvalStatus::Ok;
  ws.v.setZero();
  ws.a.setZero();
  EvalStatus st = dae.residual(t, q, ws.v, ws.a, ws.lambdaZero, ws.r0, true, ws.msg);
  ++count;
  if (st != EvalStatus::Ok) return st;
  ws.dq.setZero();
  for (int i = 0; i < ws.dq.size(); ++i) {
    ws.dq(i) = kFdStep;
    dae.retract(q, ws.dq, ws.q);
    st = dae.residual(t, ws.q, ws.v, ws.a, ws.lambdaZero, ws.r1, true, ws.msg);
    ++count;
    if (st != EvalStatus::Ok) return st;
    J.col(i) = (ws.r1.phi - ws.r0.phi) / kFdStep;
    ws.dq(i) = 0;
  }
  return EvalStatus::Ok;
}

void StateDerivatives::resize(const DaeSizes& s) {
  Fq.setZero(s.nv, s.nv);
  Fv.setZero(s.nv, s.nv);
  phiDotQ.setZero(s.nc, s.nv);
  phiDDotQ.setZero(s.nc, s.nv);
  phiDDotV.setZero(s.nc, s.nv);
}

namespace {
// Column i of F_v and g_v by a forward difference from ws.r0, the residual at
// (q, v, a, lambda); ws.v holds v.
EvalStatus velocityColumn(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda, int i,
                          StateDerivatives& out, BlockWorkspace& ws, long& count) {
  const double h = velocityIncrement(v(i));
  ws.v(i) = v(i) + h;
  const EvalStatus st = dae.residual(t, q, ws.v, a, lambda, ws.r1, true, ws.msg);
  ws.v(i) = v(i);
  ++count;
  if (st != EvalStatus::Ok) return st;
  out.Fv.col(i) = (ws.r1.F - ws.r0.F) / h;
  out.phiDDotV.col(i) = (ws.r1.phiDDot - ws.r0.phiDDot) / h;
  return EvalStatus::Ok;
}

// Columns [begin, end) of every block by forward differences from ws.r0,
// the residual at (q, v, a, lambda).
EvalStatus differenceColumns(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                             int begin, int end, StateDerivatives& out, BlockWorkspace& ws, long& count) {
  EvalStatus st = EvalStatus::Ok;
  ws.dq.setZero();
  ws.v = v;
  for (int i = begin; i < end; ++i) {
    ws.dq(i) = kFdStep;
    dae.retract(q, ws.dq, ws.q);
    ws.dq(i) = 0;
    st = dae.residual(t, ws.q, v, a, lambda, ws.r1, true, ws.msg);
    ++count;
    if (st != EvalStatus::Ok) return st;
    out.Fq.col(i) = (ws.r1.F - ws.r0.F) / kFdStep;
    out.phiDotQ.col(i) = (ws.r1.phiDot - ws.r0.phiDot) / kFdStep;
    out.phiDDotQ.col(i) = (ws.r1.phiDDot - ws.r0.phiDDot) / kFdStep;
    st = velocityColumn(dae, t, q, v, a, lambda, i, out, ws, count);
    if (st != EvalStatus::Ok) return st;
  }
  return EvalStatus::Ok;
}
}  // namespace

EvalStatus stateDerivativeBlocks(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                                 StateDerivatives& out, BlockWorkspace& ws, long& count, Mat* fastParts) {
  EvalStatus st = dae.residual(t, q, v, a, lambda, ws.r0, true, ws.msg);
  ++count;
  if (st != EvalStatus::Ok) return st;
  if (fastParts) dae.fastColumnParts(t, *fastParts);
  if (constraintRows(out) == 0 && dae.stateJacobian(t, q, v, a, out.Fq, out.Fv)) return EvalStatus::Ok;
  return differenceColumns(dae, t, q, v, a, lambda, 0, static_cast<int>(v.size()), out, ws, count);
}

EvalStatus stateDerivativeColumns(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                                  int begin, int end, StateDerivatives& out, BlockWorkspace& ws, long& count,
                                  Mat* fastParts) {
  EvalStatus st = dae.residual(t, q, v, a, lambda, ws.r0, true, ws.msg);
  ++count;
  if (st != EvalStatus::Ok) return st;
  if (fastParts) dae.fastColumnParts(t, *fastParts);
  return differenceColumns(dae, t, q, v, a, lambda, begin, end, out, ws, count);
}

EvalStatus fastVelocityColumns(Dae& dae, double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                               const Residual& base, StateDerivatives& out, BlockWorkspace& ws, long& count) {
  ws.r0 = base;
  ws.v = v;
  for (const int i : dae.fastColumns()) {
    const EvalStatus st = velocityColumn(dae, t, q, v, a, lambda, i, out, ws, count);
    if (st != EvalStatus::Ok) return st;
  }
  return EvalStatus::Ok;
}

}  // namespace bdfcar::integ
