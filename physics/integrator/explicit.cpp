#include "integrator/explicit.h"

#include <Eigen/Cholesky>

namespace bdfcar::integ {

ExplicitIntegrator::ExplicitIntegrator(Dae& dae, const ExplicitOptions& options)
    : dae_(dae), opt_(options), n_(dae.sizes()), forward_(dae) {
  bindState(own_);
  q_.setZero(n_.nq);
  lam_.setZero(n_.nc);
  for (Vec* x : {&d_, &dv_, &rate_}) x->setZero(n_.nv);
  for (int i = 0; i < 4; ++i) {
    kd_[i].setZero(n_.nv);
    kv_[i].setZero(n_.nv);
  }
  J_.setZero(n_.nc, n_.nv);
  r_.resize(n_);
  ws_.resize(n_);
}

EvalStatus ExplicitIntegrator::project(double t, Message& msg) {
  if (n_.nc == 0) return EvalStatus::Ok;
  const Vec zv = Vec::Zero(n_.nv), zc = Vec::Zero(n_.nc);
  for (int it = 0; it < 3; ++it) {
    EvalStatus st = dae_.residual(t, cur().q, cur().v, zv, zc, r_, true, msg);
    if (st == EvalStatus::Ok) st = constraintJacobianBlock(dae_, t, cur().q, J_, ws_, st_->counters.jacobianResiduals);
    if (st != EvalStatus::Ok) return st;
    const Eigen::LDLT<Mat> jjt(J_ * J_.transpose());
    if (it < 2) {  // positions: q (+) J^T (J J^T)^-1 (-phi)
      d_ = J_.transpose() * jjt.solve(-r_.phi);
      dae_.retract(cur().q, d_, q_);
      cur().q = q_;
    } else {  // velocities: v + J^T (J J^T)^-1 (-phiDot)
      cur().v += J_.transpose() * jjt.solve(-r_.phiDot);
    }
  }
  return EvalStatus::Ok;
}

EvalStatus ExplicitIntegrator::initialize(double t0, const Vec& q0, const Vec& v0, Message& msg) {
  st_->head = 0;
  st_->count = 1;
  cur().t = t0;
  cur().q = q0;
  cur().v = v0;
  dae_.beginStep(t0, q0, v0);
  return forward_.solve(t0, q0, v0, 0.0, 0.0, cur().a, cur().lambda, st_->counters, msg);
}

EvalStatus ExplicitIntegrator::accel(double t, const Vec& delta, const Vec& v, Vec& a, Message& msg) {
  dae_.retract(cur().q, delta, q_);
  return forward_.solve(t, q_, v, opt_.baumgarteAlpha, opt_.baumgarteBeta, a, lam_, st_->counters, msg);
}

bool ExplicitIntegrator::finiteState() const { return cur().q.allFinite() && cur().v.allFinite(); }

StepReport ExplicitIntegrator::step(double h) {
  StepReport rep;
  const double t = cur().t;
  dae_.beginStep(t, cur().q, cur().v);
  EvalStatus st = EvalStatus::Ok;
  if (opt_.method == ExplicitMethod::SemiImplicitEuler) {
    d_.setZero();
    st = accel(t, d_, cur().v, kv_[0], rep.message);
    if (st == EvalStatus::Ok) {
      cur().v += h * kv_[0];
      d_ = h * cur().v;
      dae_.retract(cur().q, d_, q_);
      cur().q = q_;
      cur().a = kv_[0];
    }
  } else {
    // RK4 on (delta, v) with delta' = localRate(delta, v), v' = a(q0 (+) delta, v).
    static constexpr double c[4] = {0.0, 0.5, 0.5, 1.0};
    for (int s = 0; s < 4 && st == EvalStatus::Ok; ++s) {
      if (s == 0) {
        d_.setZero();
        dv_ = cur().v;
      } else {
        d_ = (c[s] * h) * kd_[s - 1];
        dv_ = cur().v + (c[s] * h) * kv_[s - 1];
      }
      dae_.localRate(d_, dv_, kd_[s]);
      st = accel(t + c[s] * h, d_, dv_, kv_[s], rep.message);
    }
    if (st == EvalStatus::Ok) {
      d_ = (h / 6.0) * (kd_[0] + 2.0 * kd_[1] + 2.0 * kd_[2] + kd_[3]);
      cur().v += (h / 6.0) * (kv_[0] + 2.0 * kv_[1] + 2.0 * kv_[2] + kv_[3]);
      dae_.retract(cur().q, d_, q_);
      cur().q = q_;
      cur().a = kv_[3];
    }
  }
  if (st != EvalStatus::Ok) {
    rep.status = StepStatus::EvaluationFailed;
    return rep;
  }
  cur().t = t + h;
  cur().lambda = lam_;
  if (finiteState()) st = project(cur().t, rep.message);
  if (st != EvalStatus::Ok) {
    rep.status = StepStatus::EvaluationFailed;
    return rep;
  }
  ++st_->counters.steps;
  if (!finiteState()) {
    rep.status = StepStatus::Diverged;
    rep.message.set("non-finite state at t = %.6g s", cur().t);
    return rep;
  }
  if (dae_.acceptStep(cur().t, h, cur().q, cur().v, rep.message) != EvalStatus::Ok) rep.status = StepStatus::StateCheckFailed;
  return rep;
}

}  // namespace bdfcar::integ
