// RESULTS.md section: every hard case of assets/scenarios/hard/ (each with
// its [check]) run with bdfcar's default Newton policy and with the paper's
// method as published, each against the same case converged at 1 ms: what
// the policy costs per step (mean, p50 / p99 / max), what it buys, and
// whether the check holds.
#include <algorithm>
#include <vector>

#include "report/studies.h"
#include "scenario/check.h"

namespace bdfcar::app {

namespace {

std::string policyCells(const RunSummary& r) {
  const integ::Counters& c = r.result.counters;
  const scenario::StepCost& cost = r.stepCost;
  return fmt("%.0f", r.wallPerStepUs) + " | " + fmt("%.0f", cost.p50) + " / " + fmt("%.0f", cost.p99) + " / " +
         fmt("%.0f", cost.max) + " | " + std::to_string(c.refreshes) + " / " + std::to_string(c.rescues) + " / " +
         std::to_string(c.splits) + " / " + std::to_string(c.refinements);
}

}  // namespace

void hardCasesSection(std::ostream& md, int repeats) {
  md << "## 4b. Hard cases: the default Newton policy against the paper's\n\n"
     << "Each file of assets/scenarios/hard/ (sedan.toml, on relief its enveloping tyres sedan_envelope.toml; "
     << "10 ms, 2 Newton iterations, Jacobian every 200 steps; as the files say). *Default*: bdfcar's policy (when Newton stops contracting: the wheel-spin columns of "
     << "the Jacobian refreshed by a rank-4 update, Newton on to tolerance with them, then a split step; a step's "
     << "count ending at the first iteration within tolerance; "
     << "docs/DESIGN.md, integrator policy); *published*: the paper's fixed count alone (`--as-published`). "
     << "Wall time per step: the mean (median of " << repeats << " runs, no telemetry) and each "
     << "step's p50 / p99 / max (us; each the median of the " << repeats << " runs' own); refreshed / rescued / split / refined steps (refined: converged "
     << "but too far from the predictor, taken again as halves); the difference to the "
     << "same case converged at 1 ms: RMS of yaw rate and lateral acceleration (absolute: a straight run has no "
     << "peak to divide by), largest difference of the centre of mass height; and the file's [check].\n\n"
     << "| case | policy | us per step | p50 / p99 / max | refreshed / rescued / split / refined | "
     << "yaw rate RMS (rad/s) | a_y RMS (m/s^2) | z_COM max (mm) | check |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  double worstMax = 0, worstMean = 0;
  std::string worstMaxCase, worstMeanCase;
  for (const std::string& file : hardCaseFiles()) {
    const scenario::ScenarioSpec base = scenario::loadScenarioFile(file);
    const scenario::RunResult fine = converged(base);
    for (const bool published : {false, true}) {
      const scenario::ScenarioSpec spec =
          withIntegrator(base, scenario::IntegratorMethod::Bdf, 0.01, 2, 2, 200, !published);
      md << "| " << (published ? std::string() : base.name) << " | " << (published ? "published" : "default") << " | ";
      const RunSummary r = runRepeated(spec, repeats);
      if (!fine.ok) {
        md << "the 1 ms run failed: " << fine.failure << " |||||||\n";
        continue;
      }
      if (!r.result.ok) {
        md << divergedCell(r.result) << " |||||| fails |\n";
        continue;
      }
      const auto diff = [&](const char* c) {
        return compareAt(column(fine.samples, "t"), column(fine.samples, c), column(r.result.samples, "t"),
                         column(r.result.samples, c));
      };
      const scenario::CheckResult check = scenario::checkScenario(spec);
      md << policyCells(r) << " | " << fmt("%.2g", diff("yawrate").rms) << " | " << fmt("%.2g", diff("ay").rms)
         << " | " << fmt("%.1f", 1e3 * diff("z").maxAbs) << " | "
         << (check.passed ? "ok" : "fails: " + (check.failures.empty() ? std::string("?") : check.failures.front()))
         << " |\n";
      if (!published) {
        const double mx = r.stepCost.max;
        if (mx > worstMax) worstMax = mx, worstMaxCase = base.name;
        if (r.wallPerStepUs > worstMean) worstMean = r.wallPerStepUs, worstMeanCase = base.name;
      }
    }
  }
  md << "\nWith the default policy the longest step of any hard case took " << fmt("%.0f", worstMax) << " us ("
     << worstMaxCase << ") and the costliest case averaged " << fmt("%.0f", worstMean) << " us per step ("
     << worstMeanCase << "); the periodic Jacobian is taken in " << integ::BdfOptions{}.jacobianSlices
     << " slices, one at each of as many steps (integrator.jacobian_slices: a slice's columns' two residuals each "
     << "and one at its point, 5 to 7 on the sedan's linkage at sixteen, not the 75 of the whole at one step, which set "
     << "the longest step before; the published method still takes it whole). The published method is cheaper where Newton stalls because it does not converge "
     << "there: its distance to the converged run is the price.\n\n"
     << "What each measure of the policy bought, on the cases where Newton stalls most (median of " << repeats
     << " runs; residual evaluations per step include the finite-difference ones, which the default's refreshes no "
     << "longer need; the RMS against the case "
     << "converged at 1 ms):\n\n"
     << "| case | policy | us per step | p99 / max | residuals per step | LU per 100 steps | yaw rate RMS (rad/s) | "
        "a_y RMS (m/s^2) |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  struct Measure {
    const char* name;
    bool chord, fastColumns, refine, keep, rows, firstIterate, carry, slices;
  };
  const Measure measures[] = {
      {"whole Jacobian refreshed, full Newton with it (the policy before)", false, false, false, false, false, false,
       false, false},
      {"+ chord iterations while an impact's correction contracts", true, false, false, false, false, false, false,
       false},
      {"+ wheel-spin columns from the tyres, brakes and driveline alone by a rank-4 update", true, true, false, false,
       false, false, false, false},
      {"+ converged steps that miss their predictor by more than refine_error taken again as halves", true, true, true,
       false, false, false, false, false},
      {"+ the factorized matrices of the last eight h' kept, each brought to the refreshed columns by its update", true,
       true, true, true, false, false, false, false},
      {"+ in the rescue, each spin's own equation solved in its spin through the tyre's saturation", true, true, true,
       true, true, false, false, false},
      {"+ a first Newton iterate twice refine_error from the predictor halved at once, not converged first", true, true,
       true, true, true, true, false, false},
      {"+ a step after refined pieces goes on in pieces of the last one's length, doubled where its miss says a "
       "doubled one passes",
       true, true, true, true, true, true, true, false},
      {"+ the periodic Jacobian in slices of its columns, one at each of as many steps (the default: sixteen)", true, true,
       true, true, true, true, true, true}};
  for (const char* file : {"rough_lane_change.toml", "washboard_60.toml", "ramp_jump.toml"}) {
    const scenario::ScenarioSpec base = scenario::loadScenarioFile(asset(std::string("scenarios/hard/") + file));
    const scenario::RunResult fine = converged(base);
    for (const Measure& m : measures) {
      scenario::ScenarioSpec spec = base;
      spec.integrator.bdf.chordContinuation = m.chord;
      spec.integrator.bdf.fastColumnRescue = m.fastColumns;
      if (!m.refine) spec.integrator.bdf.refineError = 0;
      spec.integrator.bdf.keepFactorizations = m.keep;
      spec.integrator.bdf.fastRowSolve = m.rows;
      spec.integrator.bdf.refineFromFirstIterate = m.firstIterate;
      spec.integrator.bdf.carryRefinedPieces = m.carry;
      spec.integrator.bdf.jacobianSlices = m.slices ? base.integrator.bdf.jacobianSlices : 1;
      const RunSummary r = runRepeated(spec, repeats);
      md << "| " << (&m == &measures[0] ? base.name : std::string()) << " | " << m.name << " | ";
      if (!r.result.ok || !fine.ok) {
        md << (r.result.ok ? "the 1 ms run failed" : divergedCell(r.result)) << " |||||||\n";
        continue;
      }
      const integ::Counters& c = r.result.counters;
      const scenario::StepCost& cost = r.stepCost;
      const auto diff = [&](const char* col) {
        return compareAt(column(fine.samples, "t"), column(fine.samples, col), column(r.result.samples, "t"),
                         column(r.result.samples, col))
            .rms;
      };
      md << fmt("%.0f", r.wallPerStepUs) << " | " << fmt("%.0f", cost.p99) << " / " << fmt("%.0f", cost.max) << " | "
         << fmt("%.1f", static_cast<double>(c.residuals + c.jacobianResiduals) / std::max(1L, c.steps)) << " | "
         << fmt("%.1f", 100.0 * static_cast<double>(c.factorizations) / std::max(1L, c.steps)) << " | "
         << fmt("%.2g", diff("yawrate")) << " | " << fmt("%.2g", diff("ay")) << " |\n";
    }
  }
  md << "\nCommand (one case): `bdfcar check assets/scenarios/hard/rough_lane_change.toml` (the cost table), "
     << "`bdfcar run assets/scenarios/hard/rough_lane_change.toml --as-published` (the paper's method).\n\n";
}

}  // namespace bdfcar::app
