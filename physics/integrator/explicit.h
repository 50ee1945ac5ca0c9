// Explicit integrators on the index-1 form (accelerations from
// ForwardDynamics, Baumgarte-stabilised constraints), for the paper's
// implicit-versus-explicit comparison: classic RK4 (in local coordinates,
// Runge-Kutta-Munthe-Kaas style) and semi-implicit (symplectic) Euler.
// After each step the positions and velocities are projected back onto the
// constraints (minimum-norm Gauss-Newton), since Baumgarte alone lets a
// prescribed motion with velocity jumps (the rack's ramp) drift for ~1/alpha.
//
// No stability monitor: a stage-based estimate of h|lambda| (Hairer's
// stiffness detection) was tried and does not separate the cases here:
// with saturating tyre forces it reads ~3 at 5 ms (accurate run) and ~2.8
// at 10 ms (bounded but wrong run), because the slip mode settles into a
// limit cycle at the stability boundary. See docs/RESULTS.md, section 4.
#pragma once

#include "integrator/forward_dynamics.h"

namespace bdfcar::integ {

enum class ExplicitMethod { RK4, SemiImplicitEuler };

struct ExplicitOptions {
  ExplicitMethod method = ExplicitMethod::RK4;
  double baumgarteAlpha = 10.0;  // 1/s, velocity-level feedback
  double baumgarteBeta = 10.0;   // 1/s, position-level feedback
};

class ExplicitIntegrator final : public Integrator {
 public:
  ExplicitIntegrator(Dae& dae, const ExplicitOptions& options);
  EvalStatus initialize(double t0, const Vec& q0, const Vec& v0, Message& msg) override;
  StepReport step(double h) override;
  ExplicitIntegrator(const ExplicitIntegrator&) = delete;  // it points into its own state
  ExplicitIntegrator& operator=(const ExplicitIntegrator&) = delete;
  const SolutionPoint& current() const override { return st_->node(0); }
  const Counters& counters() const override { return st_->counters; }
  const Timers& timers() const override { return timers_; }
  void bindState(IntegratorState& s) override {
    st_ = &s;
    bindHistory(s, n_);
  }
  const IntegratorState& state() const override { return *st_; }

 private:
  // Acceleration at local coordinates delta around cur_.q with velocity v.
  EvalStatus accel(double t, const Vec& delta, const Vec& v, Vec& a, Message& msg);
  bool finiteState() const;
  EvalStatus project(double t, Message& msg);

  Dae& dae_;
  ExplicitOptions opt_;
  DaeSizes n_;
  SolutionPoint& cur() { return st_->node(0); }  // the one point of its history
  const SolutionPoint& cur() const { return st_->node(0); }
  IntegratorState own_;           // the state until bindState
  IntegratorState* st_ = &own_;
  Timers timers_;
  ForwardDynamics forward_;
  Vec q_, lam_, d_, dv_, rate_;
  Mat J_;
  Residual r_;
  BlockWorkspace ws_;
  Vec kd_[4], kv_[4];
};

}  // namespace bdfcar::integ
