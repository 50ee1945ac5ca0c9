#include "session/drive_session.h"

#include <cmath>

namespace bdfcar::app {

DriveSession::DriveSession(const scenario::ScenarioSpec& spec, const SessionOptions& options)
    : spec_(spec), options_(options) {
  restart();
}

void DriveSession::restart() {
  telemetry_.reset();
  recorder_.reset();
  sim_ = std::make_unique<scenario::Simulation>(spec_);
  sim_->prepare();  // throws on a vehicle that cannot settle
  if (!options_.telemetryPath.empty())
    telemetry_ = std::make_unique<scenario::TelemetryWriter>(options_.telemetryPath, sim_->vehicle());
  if (!options_.recordPath.empty()) recorder_ = std::make_unique<InputRecorder>(options_.recordPath, spec_.sourceFile);
  judge_.reset();
  if (sim_->course()) {
    const auto& g = sim_->vehicle().spec.geometry;
    judge_.emplace(*sim_->course(), g.length, scenario::vehicleWidth(sim_->vehicle()), g.bodyOffset);
  }
  failure_.clear();
  ticks_ = 0;
  outputEvery_ = std::max(1L, std::lround(spec_.outputInterval / spec_.integrator.step));
  sample_ = sim_->sample();
  record();
}

void DriveSession::startRecording(const std::string& path) {
  options_.recordPath = path;
  restart();
}

void DriveSession::record() {
  if (judge_) judge_->update(sample_);
  if (telemetry_) {
    const scenario::DriverInput in = sim_->lastInput();
    telemetry_->write(sample_, {sim_->steerAt(sample_.t), in.throttle, in.brake, lastIterations_, lastCorrection_});
  }
}

bool DriveSession::tick(const std::optional<scenario::DriverInput>& input) {
  if (failed()) return false;
  if (recorder_ && input) recorder_->record(ticks_, *input);
  const integ::StepReport rep = input ? sim_->step(*input) : sim_->step();
  ++ticks_;
  if (!rep.ok()) {
    failure_ = "diverged at t = " + std::to_string(time()) + " s: " + rep.message.c_str();
    return false;
  }
  lastIterations_ = rep.iterations;
  lastCorrection_ = rep.correction;
  if (ticks_ % outputEvery_ == 0) {
    sample_ = sim_->sample();
    record();
  }
  return true;
}

vehicle::VehicleView DriveSession::view() {
  sample_ = sim_->sample();
  return sim_->view();
}

vehicle::HudInfo DriveSession::hud(double realTimeFactor, double stepSeconds, const std::string& message) {
  vehicle::HudInfo h;
  h.time = sample_.t;
  h.speed = sample_.speed;
  h.steeringWheelAngle = sim_->vehicle().spec.steering.steeringWheelFull * sim_->steerAt(sample_.t);
  h.lateralAcceleration = sample_.ay;
  h.yawRate = sample_.yawRate;
  h.realTimeFactor = realTimeFactor;
  h.stepTime = stepSeconds;
  h.throttle = sim_->lastInput().throttle;
  h.brake = sim_->lastInput().brake;
  if (judge_) {
    const scenario::CourseResult& c = judge_->result();
    h.coneHits = c.coneHits;
    h.courseTime = c.entryTime < 0 ? 0.0 : (c.exitTime >= 0 ? c.exitTime : sample_.t) - c.entryTime;
  }
  h.message = failed() ? failure_ : message;
  return h;
}

const std::optional<scenario::CourseResult> DriveSession::courseResult() const {
  if (!judge_) return std::nullopt;
  return judge_->result();
}

double DriveSession::steeringFeel() const {
  // Full feel at the rack force of a 0.5 g corner at speed (~3 kN on this car).
  constexpr double kFullFeelForce = 3000.0;
  return std::clamp(-sample_.rackForce / kFullFeelForce, -1.0, 1.0);
}

}  // namespace bdfcar::app
