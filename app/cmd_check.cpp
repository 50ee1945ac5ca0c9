// `bdfcar check [FILES|DIRS]`: runs hard cases (scenario files with a
// [check] table, by default assets/scenarios/hard/) and prints a table:
// case, outcome, us per step p50 / p99 / max, refreshed / rescued / split
// steps; exits 3 when a check fails.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli_errors.h"
#include "commands.h"
#include "interrupt.h"
#include "scenario/check.h"
#include "scenario_overrides.h"

namespace bdfcar::app {

namespace {

struct CheckArgs {
  std::vector<std::string> paths{std::string(BDFCAR_ASSET_DIR) + "/scenarios/hard"};
  ScenarioOverrides overrides;
};

// The scenario files named, folders expanded to their *.toml in name order.
std::vector<std::string> scenarioFiles(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& p : paths) {
    if (std::filesystem::is_directory(p)) {
      std::vector<std::string> in;
      for (const auto& e : std::filesystem::directory_iterator(p))
        if (e.is_regular_file() && e.path().extension() == ".toml") in.push_back(e.path().string());
      std::sort(in.begin(), in.end());
      files.insert(files.end(), in.begin(), in.end());
    } else {
      files.push_back(p);
    }
  }
  return files;
}

int runCheck(const CheckArgs& a) {
  const std::vector<std::string> files = scenarioFiles(a.paths);
  if (files.empty()) throw std::runtime_error("no scenario files (*.toml) in the paths given");
  InterruptGuard interrupts;
  std::vector<scenario::CheckResult> results;
  int failed = 0;
  for (size_t i = 0; i < files.size() && !interruptRequested(); ++i) {
    scenario::ScenarioSpec spec = loadScenario(files[i], a.overrides);
    std::fprintf(stderr, "[%zu/%zu] %s ...\n", i + 1, files.size(), spec.name.c_str());
    const auto start = std::chrono::steady_clock::now();
    results.push_back(scenario::checkScenario(spec));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const scenario::CheckResult& r = results.back();
    failed += r.passed ? 0 : 1;
    // The whole case (the car built, settled and run); the manoeuvre's
    // steps alone are a few hundredths of a second.
    std::fprintf(stderr, "[%zu/%zu] %s: %s (%.2f s)\n", i + 1, files.size(), spec.name.c_str(),
                 r.passed ? "ok" : "FAILED", seconds);
  }
  std::printf(
      "| case | check | outcome | us per step p50 / p99 / max | refreshed / rescued / split / refined |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const scenario::CheckResult& r : results) {
    std::printf("| %s | %s | %s | %.0f / %.0f / %.0f | %ld / %ld / %ld / %ld |\n", r.name.c_str(),
                r.passed ? "ok" : "FAILED", r.outcome.c_str(), r.cost.p50, r.cost.p99, r.cost.max,
                r.counters.refreshes, r.counters.rescues, r.counters.splits, r.counters.refinements);
  }
  for (const scenario::CheckResult& r : results)
    for (const std::string& f : r.failures) std::printf("%s (%s): %s\n", r.name.c_str(), r.file.c_str(), f.c_str());
  std::printf("%zu passed, %d failed\n", results.size() - failed, failed);
  if (interruptRequested()) return interruptExitStatus();
  return failed ? kExitSimulationFailed : kExitOk;
}

}  // namespace

void addCheckCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand("check", "Run hard cases (scenario files with a [check] table) and print their "
                                              "outcome and cost per step; exit 3 if a check fails");
  auto a = std::make_shared<CheckArgs>();
  cmd->add_option("paths", a->paths, "Scenario files or folders (default: assets/scenarios/hard)")
      ->check(CLI::ExistingPath);
  addOverrideOptions(*cmd, a->overrides);
  commands.push_back({cmd, [a] { return reportErrors([&] { return runCheck(*a); }); }});
}

}  // namespace bdfcar::app
