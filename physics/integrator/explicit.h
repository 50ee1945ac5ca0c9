// Explicit integrators on the index-1 form (accelerations from
// ForwardDynamics, Baumgarte-stabilised constraints), for the paper's
// implicit-versus-explicit comparison: classic RK4 (in local coordinates,
// Runge-Kutta-Munthe-Kaas style) and semi-implicit (symplectic) Euler.
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
  const SolutionPoint& current() const override { return cur_; }
  const Counters& counters() const override { return counters_; }
  const Timers& timers() const override { return timers_; }

 private:
  // Acceleration at local coordinates delta around cur_.q with velocity v.
  EvalStatus accel(double t, const Vec& delta, const Vec& v, Vec& a, Message& msg);
  bool finiteState() const;

  Dae& dae_;
  ExplicitOptions opt_;
  DaeSizes n_;
  Counters counters_;
  Timers timers_;
  ForwardDynamics forward_;
  SolutionPoint cur_;
  Vec q_, lam_, d_, dv_, rate_;
  Vec kd_[4], kv_[4];
};

}  // namespace bdfcar::integ
