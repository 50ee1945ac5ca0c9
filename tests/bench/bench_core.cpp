// Micro benchmarks of the multibody core and the BDF step on a mechanism of
// the paper vehicle's size (25 relative coordinates, 14 constraint equations):
// residual, Jacobian + LU, and one step at the paper's setting with the split
// Jacobian / residual / back-substitution from the integrator's own timers.
#include <benchmark/benchmark.h>

#include <Eigen/LU>

#include "integrator/bdf.h"
#include "integrator/dae_blocks.h"
#include "mechanisms.h"
#include "multibody/multibody_dae.h"

using namespace bdfcar;
using integ::Vec;

namespace {

struct Fixture {
  mb::Model model = test::paperTopology();
  mb::MultibodyDae dae{model};
  Vec q, v, a, lam;
  Fixture() {
    q = mb::neutralPositions(model);
    v = Vec::Zero(model.nv);
    v(0) = 20.0;
    a = Vec::Zero(model.nv);
    lam = Vec::Zero(model.nc);
  }
};

void BM_Residual(benchmark::State& st) {
  Fixture f;
  integ::Residual r;
  r.resize(f.dae.sizes());
  integ::Message msg;
  for (auto _ : st) {
    f.dae.residual(0.0, f.q, f.v, f.a, f.lam, r, true, msg);
    benchmark::DoNotOptimize(r.F.data());
  }
}
BENCHMARK(BM_Residual);

void BM_JacobianAndLU(benchmark::State& st) {
  Fixture f;
  const auto n = f.dae.sizes();
  integ::BlockWorkspace ws;
  ws.resize(n);
  integ::StateDerivatives dx;
  dx.resize(n);
  integ::Mat M(n.nv, n.nv), J(n.nc, n.nv), A(n.nv + n.nc, n.nv + n.nc), Ainv(n.nv + n.nc, n.nv + n.nc);
  Eigen::PartialPivLU<integ::Mat> lu(n.nv + n.nc);
  long count = 0;
  const double hp = 0.01;
  for (auto _ : st) {
    integ::stateDerivativeBlocks(f.dae, 0.0, f.q, f.v, f.a, f.lam, dx, ws, count);
    f.dae.massMatrix(0.0, f.q, M);
    f.dae.constraintJacobian(0.0, f.q, J);
    A.topLeftCorner(n.nv, n.nv) = M + hp * dx.Fv + hp * hp * dx.Fq;
    A.topRightCorner(n.nv, n.nc) = J.transpose();
    A.bottomLeftCorner(n.nc, n.nv) = J;
    A.bottomRightCorner(n.nc, n.nc).setZero();
    lu.compute(A);
    Ainv.noalias() = lu.inverse();
    benchmark::DoNotOptimize(Ainv.data());
  }
  st.counters["residuals_per_jacobian"] = static_cast<double>(count) / static_cast<double>(st.iterations());
}
BENCHMARK(BM_JacobianAndLU);

void BM_LUOnly(benchmark::State& st) {
  const int n = 25 + 14;
  integ::Mat A = integ::Mat::Random(n, n) + 10.0 * integ::Mat::Identity(n, n), Ainv(n, n);
  Eigen::PartialPivLU<integ::Mat> lu(n);
  for (auto _ : st) {
    lu.compute(A);
    Ainv.noalias() = lu.inverse();
    benchmark::DoNotOptimize(Ainv.data());
  }
}
BENCHMARK(BM_LUOnly);

// One 10 ms step at the paper's setting: BDF2, 2 Newton iterations, Jacobian every 200 steps.
void BM_StepPaperSetting(benchmark::State& st) {
  Fixture f;
  integ::BdfOptions o;
  o.order = 2;
  o.newtonIterations = 2;
  o.jacobianEvery = 200;
  o.refreshWhenNotContracting = false;
  o.timing = true;
  integ::BdfIntegrator bdf(f.dae, o);
  integ::Message msg;
  bdf.initialize(0.0, f.q, f.v, msg);
  long steps = 0;
  for (auto _ : st) {
    if (!bdf.step(0.01).ok() || bdf.current().t > 2.0) {
      st.PauseTiming();
      bdf.initialize(0.0, f.q, f.v, msg);
      st.ResumeTiming();
    }
    ++steps;
  }
  const auto& t = bdf.timers();
  const auto& c = bdf.counters();
  const double perStep = 1e6 / static_cast<double>(c.steps);
  st.counters["jacobian_us_per_step"] = t.jacobian * perStep;
  st.counters["residual_us_per_step"] = t.residual * perStep;
  st.counters["backsub_us_per_step"] = t.backSubstitution * perStep;
  st.counters["residual_us_each"] = 1e6 * t.residual / static_cast<double>(c.residuals);
  st.counters["backsub_us_per_iteration"] = 1e6 * t.backSubstitution / static_cast<double>(c.newtonIterations);
}
BENCHMARK(BM_StepPaperSetting);

}  // namespace

BENCHMARK_MAIN();
