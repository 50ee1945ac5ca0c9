#include "scenario/run.h"

#include "scenario/failure_hint.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace bdfcar::scenario {

Run::Run(Simulation& sim, const RunOptions& config) : sim_(sim), config_(config) {
  try {
    equilibrium_ = sim_.prepare(config_.stopRequested);
  } catch (const PrepareError&) {
    throw;  // bad vehicle data: the caller's error, not a failed run
  } catch (const PrepareInterrupted& e) {
    interruptedWhileSettling_ = e.what();  // a stop, not a failure: no step was run, nothing recorded
    return;
  } catch (const std::exception& e) {  // diverged while settling or starting: the run failed before it began
    failure_ = e.what();
    failureTime_ = sim_.time();
    return;
  }
  const ScenarioSpec& spec = sim_.spec();
  const double h = spec.integrator.step;
  totalSteps_ = std::lround(spec.duration / h);
  outputEvery_ = std::max(1L, std::lround(spec.outputInterval / h));
  if (!config_.telemetryPath.empty())
    telemetry_ = std::make_unique<TelemetryWriter>(config_.telemetryPath, sim_.vehicle(), spec.laps.enabled);
  if (sim_.course()) {
    const auto& g = sim_.vehicle().spec.geometry;
    judge_.emplace(*sim_.course(), g.length, vehicleWidth(sim_.vehicle()), g.bodyOffset);
  }
  if (spec.laps.enabled) laps_.emplace(spec.laps.line, spec.laps.width, spec.laps.sectors);
  if (config_.sample) sample_ = sim_.sample();
  if (config_.rewindable) {
    snapshotEveryTicks_ = std::max(1L, std::lround(config_.snapshotInterval / spec.tick));
    maxSnapshots_ = static_cast<size_t>(std::max(1L, std::lround(config_.snapshotHistory / config_.snapshotInterval)));
  }
  if (config_.rewindable || config_.restartable) initial_ = snapshot();
  record();
}

Run::~Run() = default;

TelemetryInputs Run::rowInputs() const {
  const DriverInput in = sim_.lastInput();
  TelemetryInputs ti{sim_.steerAt(sample_.t), in.throttle, in.brake, lastIterations_, lastCorrection_, segment_,
                     static_cast<int>(sim_.vehicle().fidelity), 0.0, sim_.powertrainChannels(), {}};
  if (laps_) ti.laps = {laps_->lap(), laps_->lapTime(sample_.t), laps_->distance()};
  return ti;
}

void Run::record() {
  if (!config_.sample) return;
  if (laps_) laps_->update(sample_.t, sample_.com.head<2>(), sample_.yaw);  // before the row, which shows the lap
  TelemetryInputs ti = rowInputs();
  ti.switchJump = sim_.takeSwitchJump();
  writeRow(ti);
  if (config_.keepSamples) {
    samples_.push_back(sample_);
    steerInputs_.push_back(ti.steer);
  }
  if (judge_) judge_->update(sample_);
  if (config_.onSample) config_.onSample(sample_);
}

bool Run::tick(const std::optional<DriverInput>& input) {
  if (failed() || finished()) return !failed();
  if (config_.rewindable && ticks_ > 0 && ticks_ % snapshotEveryTicks_ == 0 &&
      (snapshots_.empty() || snapshots_.back().ticks != ticks_)) {
    snapshots_.push_back(snapshot());
    if (snapshots_.size() > maxSnapshots_) snapshots_.pop_front();
    snapshotSinceReset_ = true;
  }
  sim_.beginTick(input);
  ++ticks_;
  for (int i = 0; i < sim_.stepsPerTick() && !finished(); ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    ++modelSteps_[static_cast<int>(sim_.vehicle().fidelity)];
    const integ::StepReport rep = sim_.step();
    if (config_.keepStepCost)
      stepSeconds_.push_back(std::chrono::duration<float>(std::chrono::steady_clock::now() - t0).count());
    ++steps_;
    if (!rep.ok()) {
      if (config_.rewindable) {
        absorbDivergence(rep);
        return true;
      }
      failure_ = std::string(integ::stepStatusName(rep.status)) + ": " + rep.message.c_str();
      // A step Newton could not take: what the car was doing and what to try.
      if (rep.status == integ::StepStatus::Diverged || (rep.status == integ::StepStatus::EvaluationFailed && rep.recoverable))
        failure_ += failureHint(sim_.sample(), sim_.vehicle().model.totalMass() * sim_.vehicle().model.gravity.norm(),
                                sim_.spec().integrator);
      failureTime_ = sim_.time();
      return false;
    }
    lastIterations_ = rep.iterations;
    lastCorrection_ = rep.correction;
    if (steps_ % outputEvery_ == 0 && config_.sample) {
      sample_ = sim_.sample();
      record();
    }
  }
  return true;
}

std::string Run::failureText() const {
  char text[64];
  std::snprintf(text, sizeof text, "the run failed at t = %.3f s: ", failureTime_);
  return text + failure_;
}

Run::Snapshot Run::snapshot() {
  return {sim_.save(), judge_, laps_, sample_, steps_, ticks_, lastIterations_, lastCorrection_};
}

void Run::restoreSnapshot(const Snapshot& s) {
  sim_.restore(s.state);
  judge_ = s.judge;
  laps_ = s.laps;
  sample_ = s.sample;
  steps_ = s.steps;
  ticks_ = s.ticks;
  lastIterations_ = s.lastIterations;
  lastCorrection_ = s.lastCorrection;
  failure_.clear();
}

// The first row of a new segment: the state the run went back to.
void Run::startSegment() {
  ++segment_;
  if (config_.sample) writeRow(rowInputs());
}

void Run::writeRow(const TelemetryInputs& in) {
  if (telemetry_) telemetry_->write(sample_, in);
  if (config_.onRow) config_.onRow(sample_, in);
}

// A divergence in a rewindable run: back to the last good snapshot. A
// snapshot the run has diverged from again before taking a newer one is
// dropped (it leads to the same failure), down to the initial state.
void Run::absorbDivergence(const integ::StepReport& rep) {
  const double at = sim_.time();
  if (!snapshotSinceReset_ && !snapshots_.empty()) snapshots_.pop_back();
  const Snapshot& back = snapshots_.empty() ? *initial_ : snapshots_.back();
  restoreSnapshot(back);
  snapshotSinceReset_ = false;
  rewoundTo_ = -1;
  ++resets_;
  startSegment();
  auto shown = [](double t) { return std::abs(t) < 5e-3 ? 0.0 : t; };  // no "-0.00"
  char text[256];
  if (rep.status == integ::StepStatus::StateCheckFailed) {
    // The check's own reason ("the car overturned", "wheel FL's centre went
    // below the ground") up to its time: what a driver needs to read.
    const std::string why = rep.message.c_str();
    std::snprintf(text, sizeof text, "%s at t = %.2f s: back to t = %.2f s (reset starts again)",
                  why.substr(0, why.find(" at t =")).c_str(), shown(at), shown(sim_.time()));
  } else {
    std::snprintf(text, sizeof text, "diverged at t = %.2f s (%s), back to t = %.2f s", shown(at),
                  integ::stepStatusName(rep.status), shown(sim_.time()));
  }
  notice_ = text;
  divergence_ = rep.message.c_str();
}

void Run::restart() {
  if (!initial_) throw std::logic_error("Run::restart needs a restartable run");
  restoreSnapshot(*initial_);
  snapshots_.clear();
  snapshotSinceReset_ = true;
  rewoundTo_ = -1;
  notice_.clear();
  startSegment();
}

bool Run::restartAt(const Place& place) {
  if (!initial_) throw std::logic_error("Run::restartAt needs a restartable run");
  const Snapshot before = snapshot();
  restoreSnapshot(*initial_);  // every part of the run state as at the start
  sim_.setStart(place.x, place.y, place.heading);
  try {
    equilibrium_ = sim_.prepare(nullptr);
  } catch (const std::exception& e) {
    // Back to where the drive was, with the old start.
    const ScenarioSpec& spec = sim_.spec();
    sim_.setStart(spec.startX, spec.startY, spec.startHeading);
    restoreSnapshot(before);
    notice_ = "cannot go to " + place.name + ": " + e.what();
    return false;
  }
  steps_ = ticks_ = 0;
  snapshots_.clear();
  snapshotSinceReset_ = true;
  rewoundTo_ = -1;
  if (judge_) {
    const auto& g = sim_.vehicle().spec.geometry;
    judge_.emplace(*sim_.course(), g.length, vehicleWidth(sim_.vehicle()), g.bodyOffset);
  }
  if (laps_) laps_.emplace(sim_.spec().laps.line, sim_.spec().laps.width, sim_.spec().laps.sectors);
  if (config_.sample) sample_ = sim_.sample();
  initial_ = snapshot();
  notice_.clear();
  startSegment();
  return true;
}

void Run::closeOutputs() {
  if (telemetry_) telemetry_->close();
}

bool Run::rewind() {
  if (!config_.rewindable) return false;
  // The newest snapshot taken before this tick; a snapshot taken at this very
  // tick (nothing has run since) is skipped so that a press always goes back.
  // A press shortly after the last rewind goes on from where that one landed
  // (the snapshot there would otherwise be found again, and a held key, a
  // press every few ticks, would not get past it).
  const bool chained = rewoundTo_ >= 0 && ticks_ - rewoundTo_ < kRewindChain * snapshotEveryTicks_;
  const long before = chained ? rewoundTo_ : ticks_;
  while (!snapshots_.empty() && snapshots_.back().ticks >= before) snapshots_.pop_back();
  if (snapshots_.empty()) {
    if (ticks_ == 0) return false;
    restoreSnapshot(*initial_);
  } else {
    restoreSnapshot(snapshots_.back());
  }
  rewoundTo_ = ticks_;
  snapshotSinceReset_ = true;
  startSegment();
  return true;
}

std::optional<CourseResult> Run::course() const {
  if (!judge_) return std::nullopt;
  return judge_->result();
}

StepCost stepCost(std::vector<float> s) {
  if (s.empty()) return {};
  // The ranks by selection, not a sort: each partition leaves the rank's
  // value in place and the larger ones above it (the next, higher rank is
  // selected among those, the one placed left where it is).
  auto rank = [&](double q) { return std::min(s.size() - 1, static_cast<size_t>(q * (s.size() - 1) + 0.5)); };
  const size_t i50 = rank(0.5), i99 = rank(0.99);
  std::nth_element(s.begin(), s.begin() + i50, s.end());
  if (i99 > i50) std::nth_element(s.begin() + i50 + 1, s.begin() + i99, s.end());
  const float max = *std::max_element(s.begin() + i99, s.end());
  return {1e6 * s[i50], 1e6 * s[i99], 1e6 * max};
}

RunResult runScenario(Simulation& sim, const RunOptions& options) {
  RunResult r;
  std::optional<Run> run;
  run.emplace(sim, options);
  r.equilibrium = run->equilibrium();
  r.interruptedWhileSettling = run->interruptedWhileSettling();
  r.interrupted = !r.interruptedWhileSettling.empty();
  const auto wall0 = std::chrono::steady_clock::now();
  while (!run->finished() && run->tick(std::nullopt)) {
    if (options.stopRequested && options.stopRequested->load()) {
      r.interrupted = true;
      break;
    }
  }
  run->closeOutputs();
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  r.ok = !run->failed();
  r.failure = run->failure();
  r.failureTime = run->failureTime();
  r.steps = run->steps();
  r.simulatedSeconds = r.steps * sim.spec().integrator.step;
  r.course = run->course();
  if (const LapTimer* l = run->laps()) r.laps = l->laps();
  r.counters = sim.counters();
  r.timers = sim.timers();
  r.fidelitySwitches = sim.fidelitySwitches();
  r.fidelity = sim.fidelityState();
  r.stepsPerModel = run->stepsPerModel();
  r.samples = std::move(run->samples());
  r.stepSeconds = std::move(run->stepSeconds());
  r.steerInputs = std::move(run->steerInputs());
  return r;
}

}  // namespace bdfcar::scenario
