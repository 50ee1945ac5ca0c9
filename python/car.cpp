#include "car.h"

#include <algorithm>
#include <cmath>

#include "scenario/run_state_bytes.h"

namespace bdfcar::python {

const std::vector<std::string>& observationNames() {
  static const std::vector<std::string> names = {
      "time_s",   "x_m",     "y_m",     "yaw_rad",   "vx_mps",    "vy_mps",  "yawrate_radps",
      "ax_mps2",  "ay_mps2", "roll_rad", "pitch_rad", "speed_mps", "steer_in"};
  return names;
}

namespace {

std::unique_ptr<scenario::Simulation> settled(const std::shared_ptr<const scenario::World>& world) {
  auto sim = std::make_unique<scenario::Simulation>(world);
  try {
    sim->prepare();
  } catch (const scenario::PrepareError&) {
    throw;  // bad vehicle data
  } catch (const std::exception& e) {
    throw SimulationError(std::string("the car diverged while it settled: ") + e.what());
  }
  return sim;
}

}  // namespace

Car::Car(const std::string& scenarioPath, const app::ScenarioOverrides& overrides, const Car* sceneOf)
    : world_(scenario::buildWorld(app::loadScenario(scenarioPath, overrides),
                                  sceneOf ? sceneOf->world_->scene : nullptr)),
      sim_(settled(world_)),
      initial_(sim_->save()),
      rowMaker_(world_->vehicle) {
  startRow();
}

Car::Car(const Car& other)
    : world_(other.world_), sim_(settled(world_)), initial_(sim_->save()), rowMaker_(world_->vehicle) {
  startRow();
}

// The first telemetry row fixes the references of dz_com_m and rack_m.
void Car::startRow() {
  scenario::TelemetryRowMaker::Values values;
  const vehicle::VehicleSample s = sim_->sample();
  rowMaker_.fill(s, {}, values);
}

void Car::reset() {
  sim_->restore(initial_);
  failure_.clear();
  last_ = {};
}

void Car::tick(const std::optional<scenario::DriverInput>& input) {
  if (failed()) throw SimulationError("the car failed (" + failure_ + "): reset() or restore() it before it steps again");
  sim_->beginTick(input);
  for (int i = 0; i < sim_->stepsPerTick(); ++i) {
    last_ = sim_->step();
    if (!last_.ok()) {
      char at[64];
      std::snprintf(at, sizeof at, "at t = %.3f s: ", sim_->time());
      failure_ = at + std::string(integ::stepStatusName(last_.status)) + ": " + last_.message.c_str();
      throw SimulationError(failure_);
    }
  }
}

void Car::observation(double* out) {
  const vehicle::VehicleSample s = sim_->sample();
  const double values[kObservationSize] = {s.t,  s.com.x(), s.com.y(), s.yaw,   s.vx,    s.vy,
                                           s.yawRate, s.ax, s.ay, s.roll, s.pitch, s.speed,
                                           sim_->steerAt(s.t)};
  std::copy(values, values + kObservationSize, out);
}

void Car::telemetryRow(double* out) {
  const vehicle::VehicleSample s = sim_->sample();
  const scenario::DriverInput in = sim_->lastInput();
  scenario::TelemetryInputs ti{sim_->steerAt(s.t), in.throttle, in.brake, last_.iterations, last_.correction, 0,
                               fidelity(), sim_->takeSwitchJump(), sim_->powertrainChannels()};
  scenario::TelemetryRowMaker::Values values;
  rowMaker_.fill(s, ti, values);
  std::copy(values.begin(), values.begin() + rowMaker_.columns(), out);
}

vehicle::VehicleView Car::view() {
  sim_->sample();
  return sim_->view();
}

vehicle::HudInfo Car::hud() {
  const vehicle::VehicleSample s = sim_->sample();
  vehicle::HudInfo h;
  h.time = s.t;
  h.speed = s.speed;
  h.lateralAcceleration = s.ay;
  h.longitudinalAcceleration = s.ax;
  h.yawRate = s.yawRate;
  h.steeringWheelAngle = sim_->vehicle().spec.steering.steeringWheelFull * sim_->steerAt(s.t);
  h.throttle = sim_->lastInput().throttle;
  h.brake = sim_->lastInput().brake;
  h.realTimeLabel = "";
  return h;
}

std::vector<char> Car::save() { return sim_->saveBytes(); }

void Car::restore(const std::vector<char>& bytes) {
  sim_->restoreBytes(bytes);
  failure_.clear();
  last_ = {};
}

}  // namespace bdfcar::python
