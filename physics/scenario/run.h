// The one run driver of every command (`run`, `render`, `demo`, `drive`, the
// report and the tests): prepares a Simulation, advances it tick by tick
// with a driver's input, records telemetry and samples at the output
// interval, judges the course, and words a failure one way. A rewindable run
// also keeps the initial state (restart is an assignment) and snapshots every
// snapshotInterval of simulated time; on a divergence it goes back to the
// last good snapshot instead of stopping. Interactive drawing, devices and
// input recording are the callers' (app/session, app/interactive).
#pragma once

#include <array>

#include <atomic>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenario/course_judge.h"
#include "scenario/lap_timer.h"
#include "scenario/simulation.h"
#include "scenario/telemetry.h"

namespace bdfcar::scenario {

struct RunOptions {
  std::string telemetryPath;        // empty: no file
  bool sample = true;               // false: no samples at all (timing the steps alone)
  bool keepSamples = true;          // keep every sample in memory (RunResult::samples)
  bool keepStepCost = true;         // keep every step's wall time (RunResult::stepSeconds)
  // Called after each recorded sample (e.g. a course judge).
  std::function<void(const vehicle::VehicleSample&)> onSample;
  // Called with every telemetry row (the file's, when there is one): the
  // sample and the row's other quantities (TelemetryRowMaker makes the row).
  std::function<void(const vehicle::VehicleSample&, const TelemetryInputs&)> onRow;
  // Rewind: keep the initial state and a snapshot every snapshotInterval of
  // simulated time for the last snapshotHistory; a divergence then resets to
  // the last good snapshot (a message says so) instead of ending the run.
  bool rewindable = false;
  bool restartable = false;         // keep the initial state for restart() (implied by rewindable)
  // Set (by a signal handler) to end runScenario cleanly after the current tick.
  const std::atomic<bool>* stopRequested = nullptr;
  double snapshotInterval = 0.5;    // s
  double snapshotHistory = 30.0;    // s
};

struct RunResult {
  bool ok = true;
  std::string failure;              // at which time and which check, when !ok
  double failureTime = 0;
  vehicle::EquilibriumReport equilibrium;
  long steps = 0;                   // manoeuvre steps (settling excluded)
  integ::Counters counters;         // whole run, settling included
  integ::Timers timers;
  double wallSeconds = 0;           // manoeuvre only
  double simulatedSeconds = 0;      // manoeuvre only
  std::vector<vehicle::VehicleSample> samples;  // one per output interval (when kept)
  std::vector<double> steerInputs;  // steering input per sample
  std::optional<CourseResult> course;  // when the scenario has a course
  std::vector<LapRecord> laps;      // the laps completed, when the scenario times laps
  bool interrupted = false;         // ended early on options.stopRequested
  std::string interruptedWhileSettling;  // not empty: stopped before the run began (what prepare said)
  std::vector<float> stepSeconds;   // wall time of each manoeuvre step (per-step cost)
  long fidelitySwitches = 0;        // model switches under `[fidelity] suspension = "auto"`
  FidelityPolicy::State fidelity;   // `auto`'s at the end: switches refused, largest jumps
  std::array<long, 3> stepsPerModel{};  // manoeuvre steps per vehicle::Fidelity (linkage, kinematic, planar)
};

// p50 / p99 / max of per-step wall times, in microseconds.
struct StepCost {
  double p50 = 0, p99 = 0, max = 0;
};
StepCost stepCost(std::vector<float> seconds);

class Run {
 public:
  // Prepares the simulation and records the first sample. A run that
  // diverges while settling is a failed run (failed()); a vehicle that cannot
  // be assembled or settled statically (PrepareError) and a telemetry file
  // that cannot be opened (OutputError) throw.
  Run(Simulation& sim, const RunOptions& config);
  ~Run();

  // One driver tick: the given input (a person's, a replay's) or, with
  // nullopt, the scenario's own driver; then the tick's integration steps
  // (fewer at the end of the manoeuvre). Returns false once the run failed.
  bool tick(const std::optional<DriverInput>& input);
  // Back to the start of the manoeuvre (restartable runs: an assignment).
  void restart();
  // The manoeuvre again from one of the scene's places (restartable runs):
  // the car assembled, settled and started there as at the scenario's start,
  // a new telemetry segment; restart() comes back here from then on. False
  // (and the run as it was, notice() saying why) when the car cannot start
  // there (off the terrain, against a wall).
  bool restartAt(const Place& place);
  // One snapshot (snapshotInterval) back, rewindable runs; false when there
  // is none. A rewind soon after another (within kRewindChain intervals of
  // driving since where that one landed) goes on from there, one more
  // snapshot back: repeated or held, it keeps going back, paused or driving,
  // up to snapshotHistory.
  bool rewind();
  static constexpr long kRewindChain = 2;
  // Writes the telemetry out and closes it; throws OutputError on a write error.
  void closeOutputs();
  // The telemetry's segment: 0 from the start, +1 at each restart, rewind
  // and divergence reset (a column of its own, so nothing is overwritten).
  int segment() const { return segment_; }

  bool failed() const { return !failure_.empty(); }
  // Not empty: the stop flag was set while the car settled (Simulation::prepare).
  const std::string& interruptedWhileSettling() const { return interruptedWhileSettling_; }
  const std::string& failure() const { return failure_; }    // "diverged: Newton ..." 
  double failureTime() const { return failureTime_; }
  // The one wording of a failure for every command.
  std::string failureText() const;
  bool finished() const { return failed() || steps_ >= totalSteps_; }
  long steps() const { return steps_; }
  long ticks() const { return ticks_; }
  const std::array<long, 3>& stepsPerModel() const { return modelSteps_; }
  double time() const { return sim_.time(); }
  // Divergences absorbed by going back to a snapshot: how many, the last one
  // in a line for the HUD, and what the integrator said of it.
  int resets() const { return resets_; }
  const std::string& notice() const { return notice_; }
  const std::string& lastDivergence() const { return divergence_; }
  size_t snapshots() const { return snapshots_.size(); }

  Simulation& simulation() { return sim_; }
  const vehicle::EquilibriumReport& equilibrium() const { return equilibrium_; }
  const vehicle::VehicleSample& lastSample() const { return sample_; }
  std::optional<CourseResult> course() const;
  // The lap timing of a scenario with [laps] (nullptr without).
  const LapTimer* laps() const { return laps_ ? &*laps_ : nullptr; }
  // Moves the kept samples out (RunResult).
  std::vector<vehicle::VehicleSample>& samples() { return samples_; }
  std::vector<double>& steerInputs() { return steerInputs_; }
  // The wall time of every manoeuvre step so far (s).
  std::vector<float>& stepSeconds() { return stepSeconds_; }

 private:
  // What a rewind restores: the simulation's run state and the driver's
  // bookkeeping around it.
  struct Snapshot {
    RunState state;
    std::optional<CourseJudge> judge;
    std::optional<LapTimer> laps;
    vehicle::VehicleSample sample;
    long steps = 0, ticks = 0;
    int lastIterations = 0;
    double lastCorrection = 0;
  };
  Snapshot snapshot();
  void restoreSnapshot(const Snapshot& s);
  void record();
  void writeRow(const TelemetryInputs& in);  // to the file and onRow
  TelemetryInputs rowInputs() const;
  void startSegment();
  void absorbDivergence(const integ::StepReport& rep);

  Simulation& sim_;
  RunOptions config_;
  vehicle::EquilibriumReport equilibrium_;
  std::unique_ptr<TelemetryWriter> telemetry_;
  std::optional<CourseJudge> judge_;
  std::optional<LapTimer> laps_;  // the scenario's [laps]
  vehicle::VehicleSample sample_;
  std::vector<vehicle::VehicleSample> samples_;
  std::vector<double> steerInputs_;
  std::vector<float> stepSeconds_;
  long steps_ = 0, ticks_ = 0, totalSteps_ = 0, outputEvery_ = 1;
  std::string interruptedWhileSettling_;
  std::array<long, 3> modelSteps_{};
  int lastIterations_ = 0;
  double lastCorrection_ = 0;
  std::string failure_;
  double failureTime_ = 0;
  // Rewind.
  std::optional<Snapshot> initial_;
  std::deque<Snapshot> snapshots_;
  long snapshotEveryTicks_ = 0;
  size_t maxSnapshots_ = 0;
  bool snapshotSinceReset_ = true;
  long rewoundTo_ = -1;  // the tick the last rewind landed at (-1: none since a restart or a reset)
  int resets_ = 0, segment_ = 0;
  std::string notice_, divergence_;
};

// A whole scenario with its scripted driver, start to end: telemetry to
// options.telemetryPath, samples kept when asked. A run that fails is a
// result (RunResult::ok, failure); bad vehicle data and outputs that cannot
// be written throw (PrepareError, OutputError).
RunResult runScenario(Simulation& sim, const RunOptions& options = {});

}  // namespace bdfcar::scenario
