// The derived rungs' Newton (FidelitySpec::newtonIterations): to tolerance
// by default, where the linkage keeps the paper's fixed two. Their
// equations are an ODE with a smooth residual: from the BDF predictor one
// iteration is within tolerance at many steps (not all: it iterates where
// the motion asks), and it may not cost accuracy: against the rung's own run
// converged at 0.5 ms it is as close as the fixed two.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <string>

#include "run_error.h"
#include "scenario/run.h"
#include "scenario/scenario_spec.h"

namespace bdfcar {
namespace {

using testing_run_error::yawAndLateralRmsPercent;

scenario::ScenarioSpec onRung(const char* file, vehicle::Fidelity rung, double step, int derivedNewton) {
  scenario::ScenarioSpec s = scenario::loadScenarioFile(std::string(BDFCAR_SOURCE_DIR) + "/assets/scenarios/" + file);
  s.fidelity.suspension = rung;
  s.fidelity.newtonIterations = derivedNewton;
  s.integrator.step = step;
  return s;
}

scenario::RunResult run(const scenario::ScenarioSpec& s) {
  scenario::Simulation sim(s);
  scenario::RunResult r = scenario::runScenario(sim, {});
  EXPECT_TRUE(r.ok) << r.failure;
  return r;
}

struct Case {
  const char* file;
  vehicle::Fidelity rung;
  double iterationsPerStep;  // the bound on to tolerance's mean
};

class DerivedNewton : public ::testing::TestWithParam<Case> {};

TEST_P(DerivedNewton, ToToleranceIsAboutOneIterationAStepAndAsCloseToTheConvergedRun) {
  const Case c = GetParam();
  const scenario::ScenarioSpec base = onRung(c.file, c.rung, 0.01, 0);
  ASSERT_EQ(base.integrator.bdf.newtonIterations, 2) << "the scene's linkage count (the paper's)";
  scenario::ScenarioSpec fineSpec = onRung(c.file, c.rung, 0.0005, 0);
  fineSpec.integrator.bdf.jacobianEvery = 1;
  const scenario::RunResult fine = run(fineSpec);
  const scenario::RunResult tolerance = run(base);
  const scenario::RunResult fixed = run(onRung(c.file, c.rung, 0.01, 2));
  ASSERT_TRUE(fine.ok && tolerance.ok && fixed.ok);
  // The fixed count takes its two iterations at every step; to tolerance
  // as many as the motion asks (whole run, settling included: the J-turn's
  // planar / kinematic 1.15 / 1.31, the sine with dwell's 1.70 / 1.90: its
  // steering at 0.7 Hz moves the predictor off by more): well under two on
  // the J-turn, and never a runaway.
  const double perStep = double(tolerance.counters.newtonIterations) / double(tolerance.counters.substeps);
  EXPECT_NEAR(double(fixed.counters.newtonIterations) / double(fixed.counters.substeps), 2.0, 0.05);
  EXPECT_LT(perStep, c.iterationsPerStep);
  std::printf("%s on %s: %.3f iterations a step; %.3f %% from the converged run (fixed two: %.3f %%)\n",
              vehicle::fidelityName(c.rung), c.file, perStep, yawAndLateralRmsPercent(fine, tolerance),
              yawAndLateralRmsPercent(fine, fixed));
  // Against the converged run (measured: planar J-turn 0.54 / 0.54 %,
  // kinematic J-turn 0.33 / 0.33 %, planar sine with dwell 0.12 / 0.20 %,
  // kinematic 0.04 / 0.11 %: to tolerance / fixed two) within a tenth of a
  // per cent of the fixed count's error.
  const double eTolerance = yawAndLateralRmsPercent(fine, tolerance), eFixed = yawAndLateralRmsPercent(fine, fixed);
  EXPECT_LT(eTolerance, eFixed + 0.1) << "fixed two " << eFixed << " %";
  EXPECT_LT(eTolerance, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Rungs, DerivedNewton,
                         ::testing::Values(Case{"jturn.toml", vehicle::Fidelity::Planar, 1.5},
                                           Case{"jturn.toml", vehicle::Fidelity::Kinematic, 1.5},
                                           Case{"hard/sine_with_dwell_80.toml", vehicle::Fidelity::Planar, 2.5},
                                           Case{"hard/sine_with_dwell_80.toml", vehicle::Fidelity::Kinematic, 2.5}),
                         [](const auto& info) {
                           std::string name = std::string(vehicle::fidelityName(info.param.rung)) + "_" + info.param.file;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace bdfcar
