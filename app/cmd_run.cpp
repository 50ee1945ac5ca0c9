// `bdfcar run SCENARIO.toml --out FILE.csv [overrides]`: a batch run with
// telemetry and a one-line summary.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli_errors.h"
#include "interrupt.h"
#include "scenario/row_file.h"
#include "commands.h"
#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "scenario/run_metrics.h"
#include "scenario/standard_tests.h"
#include "scenario_overrides.h"

namespace bdfcar::app {

namespace {

// The run's metrics (run_metrics.h), with its standard test's when it has
// one: printed, and written to metricsPath as CSV (a .csv name) or JSON.
void reportMetrics(const scenario::ScenarioSpec& spec, const scenario::Simulation& sim, const scenario::RunResult& r,
                   const std::string& metricsPath) {
  std::vector<scenario::Metric> metrics = scenario::runMetrics(r);
  std::string json;
  if (spec.standardTest != scenario::StandardTest::None) {
    const scenario::StandardTestReport report = scenario::standardTestReport(
        spec.standardTest, scenario::timeHistory(r, sim.vehicle()));
    std::printf("%s", report.text.c_str());
    metrics.insert(metrics.end(), report.metrics.begin(), report.metrics.end());
    json = report.json;  // the test's own structure (docs/STANDARD_TESTS.md)
  }
  if (metricsPath.empty()) return;
  const bool csv = metricsPath.size() > 4 && metricsPath.compare(metricsPath.size() - 4, 4, ".csv") == 0;
  scenario::RowFile f(metricsPath);
  f.append(csv ? scenario::metricsCsv(metrics) : json.empty() ? scenario::metricsJson(metrics) : json);
  f.close();
}

int runRun(const std::string& path, const std::string& out, const std::string& metrics, const std::string& laps,
           const ScenarioOverrides& ov) {
  scenario::ScenarioSpec spec = loadScenario(path, ov);
  if (!laps.empty() && !spec.laps.enabled)
    throw std::runtime_error("--laps " + laps + ": " + path + " times no laps (it has no [laps] table)");
  auto refuseDestroyingOutputs = [&] {
    scenario::refuseSameOutputs({{"--out", out}, {"--metrics", metrics}, {"--laps", laps}});
    for (const std::string& o : {out, metrics, laps})
      scenario::refuseOverwritingInputs(o, {path, spec.vehicleFile, spec.terrainFile});
  };
  refuseDestroyingOutputs();  // before the vehicle and terrain are read (an output over them)
  scenario::Simulation sim(spec);
  refuseDestroyingOutputs();  // and with every file the world read (includes, meshes); no output is open yet
  InterruptGuard interrupts;
  scenario::RunOptions opt;
  opt.telemetryPath = out;
  // Metrics need the whole time history.
  opt.keepSamples = spec.standardTest != scenario::StandardTest::None || !metrics.empty();
  opt.stopRequested = &interruptRequested();
  // Without a telemetry file (and no course to judge) nothing is sampled:
  // the printed time per step is then the step alone.
  opt.sample = !out.empty() || sim.course().has_value() || opt.keepSamples || spec.laps.enabled;
  const scenario::RunResult r = scenario::runScenario(sim, opt);
  if (!r.interruptedWhileSettling.empty()) {
    std::fprintf(stderr, "%s: stopped by %s before the run began (%s)%s\n", spec.name.c_str(), interruptSignalName(),
                 r.interruptedWhileSettling.c_str(), out.empty() ? "" : ": no telemetry written");
    return interruptExitStatus();
  }
  if (!r.ok) {
    std::fprintf(stderr, "error: %s: the run failed at t = %.3f s: %s\n", path.c_str(), r.failureTime, r.failure.c_str());
    // A sweep's summary keeps the failed case (ok = 0) with what it reached.
    if (!metrics.empty()) reportMetrics(spec, sim, r, metrics);
    return 3;
  }
  const auto& c = r.counters;
  const double perStepUs = r.steps > 0 ? 1e6 * r.wallSeconds / r.steps : 0;
  const scenario::StepCost cost = scenario::stepCost(r.stepSeconds);
  std::printf("%s: %ld steps of %.4g s, %ld Newton iterations, %ld Jacobians, %ld wheel-spin column refreshes, "
              "%ld factorizations (%ld refreshed, %ld rescued, %ld split, %ld refined), %.2f us per step "
              "(p50 %.1f, p99 %.1f, max %.1f), real-time factor %.0f\n",
              spec.name.c_str(), r.steps, spec.integrator.step, c.newtonIterations, c.jacobians, c.columnRefreshes,
              c.factorizations, c.refreshes, c.rescues, c.splits, c.refinements, perStepUs, cost.p50, cost.p99,
              cost.max,
              r.wallSeconds > 0 ? r.simulatedSeconds / r.wallSeconds : 0.0);
  if (spec.fidelity.automatic) {
    std::printf("fidelity auto: %ld switch%s (largest chassis jump %.2f mm, %.2f mrad; %ld refused: they would have "
                "moved the chassis); steps on the linkage %ld, kinematic %ld, planar %ld\n",
                r.fidelitySwitches, r.fidelitySwitches == 1 ? "" : "es", 1e3 * r.fidelity.maxJump,
                1e3 * r.fidelity.maxTurn, r.fidelity.refused, r.stepsPerModel[0], r.stepsPerModel[1],
                r.stepsPerModel[2]);
    for (const std::string& why : sim.world().autoRefusals) std::printf("fidelity auto: %s\n", why.c_str());
  }
  if ((spec.standardTest != scenario::StandardTest::None || !metrics.empty()) && !r.interrupted)
    reportMetrics(spec, sim, r, metrics);
  if (spec.laps.enabled) {
    std::printf("%s", r.laps.empty() ? "laps: none completed\n" : scenario::lapsSummary(r.laps).c_str());
    if (!laps.empty()) scenario::writeLapFile(laps, r.laps, spec.laps.sectors);
  }
  if (r.course) {
    const auto& cr = *r.course;
    std::printf("ISO 3888-%d course: %s, peak lateral acceleration %.2f m/s^2 (%.2f g)\n", sim.course()->part,
                scenario::courseVerdict(cr).c_str(), cr.peakLateralAcceleration, cr.peakLateralAcceleration / 9.81);
    if (!r.interrupted) return cr.passed && cr.exitTime >= 0 ? 0 : 4;
  }
  if (r.interrupted) {
    std::fprintf(stderr, "%s: stopped by %s at t = %.3f s%s%s\n", spec.name.c_str(), interruptSignalName(),
                 r.simulatedSeconds, out.empty() ? "" : "; the telemetry is complete to its last row: ", out.c_str());
    return interruptExitStatus();
  }
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand("run", "Run a scenario without a window and write its telemetry");
  auto path = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto ov = std::make_shared<ScenarioOverrides>();
  cmd->add_option("scenario", *path, "Scenario file (assets/scenarios/*.toml)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", *out, "Telemetry CSV to write (without it the steps alone are timed)");
  auto metrics = std::make_shared<std::string>();
  cmd->add_option("--metrics", *metrics,
                  "Write the run's metrics here (docs/STANDARD_TESTS.md): peaks, final speed, the course's verdict, "
                  "and a standard test's metrics ([metrics] test); CSV when the name ends in .csv, else JSON");
  auto laps = std::make_shared<std::string>();
  cmd->add_option("--laps", *laps, "A scenario that times laps ([laps]): write its laps here, one CSV row each");
  addOverrideOptions(*cmd, *ov);
  commands.push_back({cmd, [=] { return reportErrors([&] { return runRun(*path, *out, *metrics, *laps, *ov); }); }});
}

}  // namespace bdfcar::app
