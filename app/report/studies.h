// The numerical studies behind docs/RESULTS.md: runs of the scenarios with
// chosen integrator settings, compared with the independent reference and
// with the project's own converged runs.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "scenario/run.h"
#include "scenario/scenario_spec.h"

namespace bdfcar::app {

// A column of samples by name (the telemetry's quantities used in comparisons).
std::vector<double> column(const std::vector<vehicle::VehicleSample>& s, const std::string& name);

struct Difference {
  double rmsPercent = 0;  // RMS difference as % of the reference's peak |value|
  double rms = 0;         // RMS difference in the quantity's units
  double maxAbs = 0;
};
// Compares a run with a reference at the run's sample times (the reference
// interpolated linearly in time): runs at 20 ms have one sample per 20 ms.
Difference compareAt(const std::vector<double>& refTime, const std::vector<double>& reference,
                     const std::vector<double>& runTime, const std::vector<double>& run);

struct RunSummary {
  scenario::RunResult result;
  double wallPerStepUs = 0;  // median over repeats of wall time per manoeuvre step, no telemetry
  // Each of the timed runs' per-step p50 / p99 / max, the median over the
  // repeats of each (a single run's max is one scheduler hiccup away).
  scenario::StepCost stepCost;
};

// Runs a scenario `repeats` times without samples (as `bdfcar run` with no
// telemetry: the timing; none for 0), then once more with them (the result
// kept).
RunSummary runRepeated(const scenario::ScenarioSpec& spec, int repeats);

// Two scenarios timed in turn, a then b, `repeats` times (a machine whose
// speed drifts over the minutes slows both of a pair alike): each one's
// summary as runRepeated's, and the median of the pairs' ratios a / b of
// wall time per step (0 for none).
struct PairedSummary {
  RunSummary a, b;
  double ratio = 0;
};
PairedSummary runPaired(const scenario::ScenarioSpec& a, const scenario::ScenarioSpec& b, int repeats);

// refresh: bdfcar's Newton policy (a refresh when Newton stops contracting,
// a step's count ended at the first iteration within tolerance); false: the
// paper's method as published (the count in full, nothing else).
scenario::ScenarioSpec withIntegrator(scenario::ScenarioSpec s, scenario::IntegratorMethod m, double step, int order,
                                      int newton, int jacobianEvery, bool refresh = true);

// Paths under assets/ (BDFCAR_ASSET_DIR): a scenario with a chosen vehicle file.
std::string asset(const std::string& rel);
scenario::ScenarioSpec scenarioWith(const std::string& scenarioFile, const std::string& vehicleFile);

// printf-formatted number for the tables.
std::string fmt(const char* format, double value);

// The hard cases: every .toml of assets/scenarios/hard/, sorted by name.
std::vector<std::string> hardCaseFiles();

// A converged run of the project's own model: 1 ms, Newton to tolerance, Jacobian every step.
scenario::RunResult converged(const scenario::ScenarioSpec& s);

// A diverged run as a table cell: when, and whether it was still settling.
std::string divergedCell(const scenario::RunResult& r);

// The command line that reproduces one run of a section.
void command(std::ostream& md, const std::string& args);

// A PNG drawn by gnuplot from a CSV (script: the plot commands after the
// terminal, grid and key settings); a note on stderr when gnuplot fails.
void writePlot(const std::string& dataPath, const std::string& png, const std::string& script);

// Section of RESULTS.md: the fidelity ladder, each rung against the linkage
// converged at 1 ms on smooth and hard manoeuvres (images under imageDir).
void fidelitySection(std::ostream& md, int repeats, const std::string& imageDir);

// Section of RESULTS.md: the sedan on PAC2002 tyres against Chrono's run with them and its own converged runs.
void tyreSection(std::ostream& md, const std::string& pac02Reference);
// Section of RESULTS.md: a vehicle's sheet and standard-test metrics (the reference sedan's by default).
void standardTestsSection(std::ostream& md, const std::string& vehicleFile);
// Section of RESULTS.md: a vehicle's K&C numbers (shownPath: the file as the command line would name it).
void kcSection(std::ostream& md, const std::string& vehicleFile, const std::string& shownPath);
// The drivable sedan's powertrain: gears, a full-throttle run, its cost per step.
void powertrainSection(std::ostream& md, int repeats);
// The shipped sweep's summary and plots (images under imageDir).
void sweepSection(std::ostream& md, const std::string& imageDir);

// Sections of RESULTS.md: work-precision diagrams (image under imageDir) and
// the hard cases' survival at long steps and with explicit methods.
void workPrecisionSection(std::ostream& md, const std::string& imageDir);
void survivalSection(std::ostream& md);

// Section of RESULTS.md: the default Newton policy against the paper's on
// hard cases (rough road, curb, jump, large steps): cost and error.
void hardCasesSection(std::ostream& md, int repeats);

// Reference telemetry columns read from a CSV with a header.
std::vector<double> csvColumn(const std::string& path, const std::string& name);

}  // namespace bdfcar::app
