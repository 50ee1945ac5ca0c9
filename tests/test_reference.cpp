// Regression against the independent reference (Chrono, 31.25 us, converged):
// the reference sedan's J-turn, at 1 ms and at the paper's setting (10 ms,
// 2 Newton iterations, Jacobian every 200 steps).
//
// Tolerance: 0.25 % RMS of the peak for yaw rate and lateral acceleration.
// Measured here: 0.05 % / 0.04 % at 1 ms. The reference itself moves by
// 0.16 % of the peak (max) between two formulations of the same model at
// 31.25 us (README, split-wrench vs standard), and the smallest real model
// error found so far (the drive torque reacting on the wheel carrier instead
// of nowhere, as the reference applies it) gave 0.57 %: the bound sits
// between what the reference can resolve and what must be caught.
#include <gtest/gtest.h>

#include "reference_data.h"
#include "scenario/run.h"
#include "scenario/scenario_spec.h"

using namespace bdfcar;

namespace {

std::string source(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/" + rel; }

struct Comparison {
  test::ColumnError yawRate, lateral, roll;
};

struct JTurnRun {
  scenario::RunResult result;
  Comparison error;
};

JTurnRun runJTurnWith(double step, int newton, int jacobianEvery, const std::string& vehicle,
                      scenario::IntegratorMethod method, const std::string& reference = "tests/data/ref_jturn.csv") {
  scenario::ScenarioSpec s = scenario::loadScenarioFile(source("assets/scenarios/jturn.toml"));
  s.vehicleFile = source("assets/vehicles/" + vehicle);
  s.integrator.method = method;
  s.integrator.step = step;
  s.integrator.bdf.newtonIterations = newton;
  s.integrator.bdf.jacobianEvery = jacobianEvery;
  scenario::Simulation sim(s);
  JTurnRun run{scenario::runScenario(sim, {}), {}};
  if (!run.result.ok) return run;
  std::vector<double> yaw, ay, roll;
  for (const auto& x : run.result.samples) {
    yaw.push_back(x.yawRate);
    ay.push_back(x.ay);
    roll.push_back(x.roll);
  }
  const test::Table ref = test::readCsv(source(reference));
  EXPECT_EQ(run.result.samples.size(), ref.values.at("time_s").size());
  run.error = {test::compareColumn(ref, yaw, "yawrate_radps"), test::compareColumn(ref, ay, "ay_mps2"),
               test::compareColumn(ref, roll, "roll_rad")};
  return run;
}

Comparison runJTurn(double step, int newton, int jacobianEvery, const std::string& vehicle = "sedan.toml") {
  const JTurnRun r = runJTurnWith(step, newton, jacobianEvery, vehicle, scenario::IntegratorMethod::Bdf);
  EXPECT_TRUE(r.result.ok) << r.result.failure;
  return r.error;
}

}  // namespace

TEST(Reference, JTurnAtOneMillisecondMatchesChrono) {
  const Comparison c = runJTurn(0.001, 2, 1);
  EXPECT_LT(c.yawRate.rmsPercent, 0.25);
  EXPECT_LT(c.lateral.rmsPercent, 0.25);
  // Roll: 0.23 % measured; the reference's roll differs by 0.05 % of its
  // peak between its own formulations; same bound.
  EXPECT_LT(c.roll.rmsPercent, 0.5);
}

TEST(Reference, JTurnAtThePapersSettingMatchesChrono) {
  // 10 ms, BDF2, 2 Newton iterations, Jacobian every 200 steps: the step the
  // reference code itself cannot run at (it diverges at 10 ms).
  const Comparison c = runJTurn(0.01, 2, 200);
  EXPECT_LT(c.yawRate.rmsPercent, 0.25);
  // The steering ramp's corners put a two-step spike into a_y at 10 ms
  // (0.19 % measured): twice the 1 ms bound.
  EXPECT_LT(c.lateral.rmsPercent, 0.5);
}

TEST(Reference, PaperTopologyStaysCloseToTheReference) {
  // Same car in the paper's Table 1 topology (strut turning with the knuckle,
  // massless rear links, equivalent rear spring): 0.22 % measured.
  const Comparison c = runJTurn(0.01, 2, 200, "paper.toml");
  EXPECT_LT(c.yawRate.rmsPercent, 0.5);
  EXPECT_LT(c.lateral.rmsPercent, 0.75);
}

TEST(Reference, ImplicitHoldsAtTenMillisecondsWhereExplicitDoesNot) {
  // The paper's claim, on the same model: at the driver's 10 ms the tyre's
  // slip mode (h lambda ~ 6) lies outside RK4's stability region (2.8). The
  // saturating tyre force either lets it blow up or holds it in a bounded
  // chatter (55 % measured); either way the run is not the car's motion.
  // Inside the region (2 ms) the same RK4 agrees with the reference (0.17 %),
  // so the failure at 10 ms is the step, not the explicit implementation.
  const JTurnRun rk4Coarse = runJTurnWith(0.01, 2, 200, "sedan.toml", scenario::IntegratorMethod::Rk4);
  if (rk4Coarse.result.ok) {
    EXPECT_GT(rk4Coarse.error.yawRate.rmsPercent, 10.0);
  }
  const JTurnRun rk4Fine = runJTurnWith(0.002, 2, 200, "sedan.toml", scenario::IntegratorMethod::Rk4);
  ASSERT_TRUE(rk4Fine.result.ok) << rk4Fine.result.failure;
  EXPECT_LT(rk4Fine.error.yawRate.rmsPercent, 0.5);
  const Comparison bdf = runJTurn(0.01, 2, 200);
  EXPECT_LT(bdf.yawRate.rmsPercent, 0.25);
}

// The sedan on PAC2002 tyres as Chrono 9.0.1 evaluates them (variant
// chrono9) against Chrono's own run with that tyre (ref_jturn_pac02.csv),
// at 1 ms and at the paper's 10 ms setting. Measured: 0.010 / 0.016 % at
// 1 ms, 0.022 / 0.23 % at 10 ms (yaw rate / a_y); the bounds are
// 1 % at 1 ms and 3 % at 10 ms, held here to 1 % at both. The textbook
// evaluation of the same file is 1.2 % away (its sign convention mirrors
// the asymmetric coefficients, and it has camber): not Chrono's tyre.
TEST(Reference, Pac2002JTurnMatchesChronosEvaluationOfTheSameFile) {
  for (double step : {0.001, 0.01}) {
    SCOPED_TRACE("step " + std::to_string(step));
    const JTurnRun r = runJTurnWith(step, 2, 200, "sedan_pac2002_chrono9.toml", scenario::IntegratorMethod::Bdf,
                                    "tests/data/ref_jturn_pac02.csv");
    ASSERT_TRUE(r.result.ok) << r.result.failure;
    EXPECT_LT(r.error.yawRate.rmsPercent, 1.0);
    EXPECT_LT(r.error.lateral.rmsPercent, 1.0);
    EXPECT_LT(r.error.roll.rmsPercent, 1.0);
  }
}
