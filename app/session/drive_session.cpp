#include "session/drive_session.h"

#include <cmath>

#include <cstdio>
#include <algorithm>
#include <stdexcept>

namespace bdfcar::app {

DriveSession::DriveSession(const scenario::ScenarioSpec& spec, const SessionOptions& options) : options_(options) {
  sim_ = std::make_unique<scenario::Simulation>(spec);
  scenario::RunOptions ro;
  ro.telemetryPath = options_.telemetryPath;
  ro.keepSamples = false;
  ro.keepStepCost = false;  // a drive may last hours: memory stays flat
  ro.rewindable = options_.rewindable;
  ro.restartable = true;
  run_ = std::make_unique<scenario::Run>(*sim_, ro);
  if (run_->failed()) throw std::runtime_error(spec.vehicleFile + ": " + run_->failure());
  if (!options_.recordPath.empty()) recorder_ = std::make_unique<InputRecorder>(options_.recordPath, spec);
  sample_ = run_->lastSample();
}

DriveSession::~DriveSession() = default;

void DriveSession::restart() {
  run_->restart();
  if (recorder_) recorder_->record({RecordedTick::Kind::Reset, {}, -1});
  sample_ = sim_->sample();
}

bool DriveSession::rewind() {
  if (!run_->rewind()) return false;
  if (recorder_) recorder_->record({RecordedTick::Kind::Rewind, {}, -1});
  sample_ = sim_->sample();
  return true;
}

bool DriveSession::goTo(int place) {
  const std::vector<scenario::Place>& places = spec().places;
  if (place < 0 || place >= static_cast<int>(places.size())) {
    notice_ = "no place " + std::to_string(place) + " in " + spec().sourceFile;
    return false;
  }
  if (!run_->restartAt(places[place])) {
    notice_ = run_->notice();
    return false;
  }
  place_ = place;
  notice_.clear();
  if (recorder_) recorder_->record({RecordedTick::Kind::Place, {}, place});
  sample_ = sim_->sample();
  return true;
}

void DriveSession::startRecording(const std::string& path) {
  if (recorder_) stopRecording();
  auto recorder = std::make_unique<InputRecorder>(path, spec());  // throws before anything changes
  run_->restart();
  // A recording replays from the scenario's start: it begins by going where the drive restarted.
  if (place_ >= 0) recorder->record({RecordedTick::Kind::Place, {}, place_});
  options_.recordPath = path;
  recorder_ = std::move(recorder);
  sample_ = sim_->sample();
}

long DriveSession::stopRecording() {
  if (!recorder_) return 0;
  const long ticks = recorder_->ticks();
  std::unique_ptr<InputRecorder> r = std::move(recorder_);
  r->close();
  return ticks;
}

void DriveSession::closeOutputs() {
  stopRecording();
  run_->closeOutputs();
}

bool DriveSession::tick(const std::optional<scenario::DriverInput>& input) {
  if (recorder_ && input && !failed() && !finished()) recorder_->record({RecordedTick::Kind::Input, *input, -1});
  const bool ok = run_->tick(input);
  sample_ = run_->lastSample();
  return ok;
}

bool DriveSession::replay(const RecordedTick& e) {
  switch (e.kind) {
    case RecordedTick::Kind::Input: return tick(e.input);
    case RecordedTick::Kind::Reset: restart(); return true;
    case RecordedTick::Kind::Rewind: rewind(); return true;
    case RecordedTick::Kind::Place: return goTo(e.place);
  }
  return true;
}

vehicle::VehicleView DriveSession::view() {
  sample_ = sim_->sample();
  vehicle::VehicleView v = sim_->view();
  if (const scenario::LapTimer* l = run_->laps()) {
    if (const std::optional<scenario::GhostPose> g = l->ghost(sample_.t)) {
      // The ghost's chassis frame where the car's is relative to its centre
      // of mass, turned to the ghost's heading, level, at the car's height.
      const Eigen::Vector3d offset = sample_.chassisRotation.transpose() * (sample_.chassisOrigin - sample_.com);
      const Eigen::Quaterniond yaw(Eigen::AngleAxisd(g->yaw, Eigen::Vector3d::UnitZ()));
      v.ghost = true;
      v.ghostChassis.rotation = yaw;
      v.ghostChassis.position = Eigen::Vector3d(g->x, g->y, sample_.com.z()) + yaw * offset;
    }
  }
  return v;
}

vehicle::HudInfo DriveSession::hud(double realTimeFactor, double stepSeconds, const std::string& message) {
  vehicle::HudInfo h;
  h.time = sample_.t;
  h.speed = sample_.speed;
  h.steeringWheelAngle = sim_->vehicle().spec.steering.steeringWheelFull * sim_->steerAt(sample_.t);
  h.lateralAcceleration = sample_.ay;
  h.longitudinalAcceleration = sample_.ax;
  h.yawRate = sample_.yawRate;
  h.realTimeFactor = realTimeFactor;
  h.stepTime = stepSeconds;
  h.model = vehicle::fidelityName(sim_->vehicle().fidelity);
  switch (sim_->vehicle().fidelity) {
    case vehicle::Fidelity::Linkage: h.members = "links: the vehicle file's members"; break;
    case vehicle::Fidelity::Kinematic: h.members = "springs: the corners' tables"; break;
    case vehicle::Fidelity::Planar: h.members = "posts: the body's roll and pitch"; break;
  }
  if (sim_->spec().fidelity.automatic) {
    const long n = sim_->fidelitySwitches();
    h.model += " (auto, " + std::to_string(n) + (n == 1 ? " switch)" : " switches)");
  }
  h.throttle = sim_->lastInput().throttle;
  h.brake = sim_->lastInput().brake;
  h.speedHold = sim_->speedHoldTarget();
  if (const scenario::Transmission* t = sim_->transmission()) {
    // The engine's throttle: the driver's, or the speed hold's working the pedal.
    const scenario::PowertrainChannels p = sim_->powertrainChannels();
    h.throttle = p.throttle;
    h.speedHold = -1.0;  // it works the throttle shown
    h.powertrain = true;
    h.gear = p.gear;
    h.engineRpm = p.engineRpm;
    h.shifting = t->shifting();
    h.handbrake = p.handbrake;
  }
  if (const auto c = run_->course()) {
    h.knockedCones = c->knockedCones;
    // Nothing to judge until the car enters the course or touches it: a free
    // drive that never goes there shows no "cones hit 0, course 0.00 s".
    if (c->entryTime >= 0 || c->coneHits > 0 || !c->passed) {
      h.coneHits = c->coneHits;
      h.courseTime = c->entryTime < 0 ? 0.0 : (c->exitTime >= 0 ? c->exitTime : sample_.t) - c->entryTime;
    }
    // A corner of the car outside the lanes or a cone hit fails the run at
    // once; through the exit gate with neither, it passes.
    if (!c->passed) h.verdict = "FAILED: " + scenario::courseVerdict(*c).substr(std::string("failed: ").size());
    else if (c->exitTime >= 0) h.verdict = "PASSED";
  }
  if (const scenario::LapTimer* l = run_->laps()) {
    h.lap = l->lap();
    h.sector = l->sector();
    h.lapTime = l->lapTime(sample_.t);
    h.lapValid = l->valid();
    if (const scenario::LapRecord* last = l->last()) h.lastLap = last->time;
    if (const scenario::LapRecord* best = l->best()) h.bestLap = best->time;
    h.lapDelta = l->delta(sample_.t);
    h.lapDeltaShown = std::isfinite(h.lapDelta);
  }
  h.mapX = sample_.com.x();
  h.mapY = sample_.com.y();
  h.mapYaw = sample_.yaw;
  h.message = failed() ? failure() : message;
  return h;
}

double DriveSession::steeringFeel() const {
  // Full feel at the rack force of a 0.5 g corner at speed (~3 kN on this car).
  constexpr double kFullFeelForce = 3000.0;
  return std::clamp(-sample_.rackForce / kFullFeelForce, -1.0, 1.0);
}

}  // namespace bdfcar::app
