// RESULTS.md section: the hard cases (scenario/hard_cases.h) run with bdfcar's default Newton policy and with the paper's
// method as published, each against the same case converged at 1 ms: what
// the refresh / rescue / split policy costs and what it buys.
#include <vector>

#include "report/studies.h"
#include "scenario/hard_cases.h"

namespace bdfcar::app {

namespace {

std::string policyCell(const RunSummary& r) {
  const integ::Counters& c = r.result.counters;
  return fmt("%.0f us", r.wallPerStepUs) + " | " + std::to_string(c.refreshes) + " / " + std::to_string(c.rescues) +
         " / " + std::to_string(c.splits);
}

}  // namespace

void hardCasesSection(std::ostream& md, int repeats) {
  md << "## 4b. Hard cases: the default Newton policy against the paper's\n\n"
     << "sedan.toml at 10 ms, 2 Newton iterations, Jacobian every 200 steps. *Default*: bdfcar's policy "
     << "(refresh a stale Jacobian when Newton stops contracting, then full Newton, then split the step); "
     << "*published*: the paper's fixed count alone (`--as-published`). Wall time per step (median of " << repeats
     << ", telemetry sampled at every step), refreshed / rescued / split steps, and the difference to the "
     << "same case converged at 1 ms: RMS of "
     << "yaw rate and lateral acceleration (absolute: a straight jump has no peak to divide by), largest "
     << "difference of the centre of mass height.\n\n"
     << "| case | policy | us per step | refreshed / rescued / split | yaw rate RMS (rad/s) | a_y RMS (m/s^2) | "
     << "z_COM max (mm) |\n"
     << "|---|---|---|---|---|---|---|\n";
  const std::vector<scenario::HardCase> cases = scenario::hardCases(BDFCAR_ASSET_DIR);
  for (const scenario::HardCase& hc : cases) {
    scenario::ScenarioSpec base = scenarioWith(hc.scenarioFile, "sedan.toml");
    hc.edit(base);
    const scenario::RunResult fine = converged(base);
    for (const bool published : {false, true}) {
      md << "| " << (published ? std::string() : hc.name) << " | " << (published ? "published" : "default") << " | ";
      const RunSummary r = runRepeated(
          withIntegrator(base, scenario::IntegratorMethod::Bdf, 0.01, 2, 2, 200, !published), repeats);
      if (!fine.ok) {
        md << "the 1 ms run failed: " << fine.failure << " ||||\n";
        continue;
      }
      if (!r.result.ok) {
        md << divergedCell(r.result) << " ||||\n";
        continue;
      }
      const auto diff = [&](const char* c) {
        return compareAt(column(fine.samples, "t"), column(fine.samples, c), column(r.result.samples, "t"),
                         column(r.result.samples, c));
      };
      md << policyCell(r) << " | " << fmt("%.2g", diff("yawrate").rms) << " | " << fmt("%.2g", diff("ay").rms) << " | "
         << fmt("%.1f", 1e3 * diff("z").maxAbs) << " |\n";
    }
  }
  md << "\nScenario edits (as a scenario file would hold them): ";
  bool first = true;
  for (const scenario::HardCase& hc : cases) {
    md << (first ? "" : "; ") << hc.name << ": `" << hc.scenarioFile << "` with " << hc.edits;
    first = false;
  }
  md << ". The test suite runs the same cases (tests/test_scenario.cpp, HardCases).\n\n"
     << "The default policy spends its extra work at impacts and on rough ground, where the paper's fixed "
     << "count leaves Newton short of convergence; on smooth manoeuvres the two coincide. On the rough road it "
     << "costs the most: most steps refresh the Jacobian (tyres lifting off and landing within a step), which "
     << "stays within real time on average but not per step; a policy with a per-step budget is the next "
     << "step for driving there.\n\n";
}

}  // namespace bdfcar::app
