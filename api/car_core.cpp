#include "car_core.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "config/toml_reader.h"
#include "scenario/row_file.h"
#include "scenario/run_state_bytes.h"

namespace bdfcar::api {

const std::vector<std::string>& observationNames() {
  static const std::vector<std::string> names = {
      "time_s",   "x_m",     "y_m",     "yaw_rad",   "vx_mps",    "vy_mps",  "yawrate_radps",
      "ax_mps2",  "ay_mps2", "roll_rad", "pitch_rad", "speed_mps", "steer_in"};
  return names;
}

app::ScenarioOverrides carOverrides(const std::optional<std::string>& vehicle, const std::optional<std::string>& fidelity,
                                    std::optional<double> step, std::optional<double> duration,
                                    const std::vector<std::string>& settings) {
  app::ScenarioOverrides ov;
  ov.vehicle = vehicle;
  ov.fidelity = fidelity;
  ov.step = step;
  ov.duration = duration;
  ov.settings = settings;
  if (fidelity) {
    scenario::FidelitySpec f;
    if (!scenario::parseFidelity(*fidelity, f))
      throw config::ConfigError("fidelity: expected linkage, kinematic, planar or auto, got \"" + *fidelity + "\"");
  }
  return ov;
}

namespace {

double checked(const char* name, double value, double lo, double hi) {
  if (!std::isfinite(value))
    throw std::invalid_argument(std::string(name) + " must be a finite number, got " + std::to_string(value));
  return std::clamp(value, lo, hi);
}

}  // namespace

scenario::DriverInput driverInput(double steer, double throttle, double brake) {
  scenario::DriverInput in;
  in.steer = checked("steer", steer, -1.0, 1.0);
  in.throttle = checked("throttle", throttle, 0.0, 1.0);
  in.brake = checked("brake", brake, 0.0, 1.0);
  return in;
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

CarCore::CarCore(const std::string& scenarioPath, const app::ScenarioOverrides& overrides, const CarCore* sceneOf)
    : world_(scenario::buildWorld(app::loadScenario(scenarioPath, overrides),
                                  sceneOf ? sceneOf->world_->scene : nullptr)),
      sim_(settled(world_)),
      initial_(sim_->save()),
      rowMaker_(world_->vehicle) {
  startRow();
}

CarCore::CarCore(const CarCore& other)
    : world_(other.world_), sim_(settled(world_)), initial_(sim_->save()), rowMaker_(world_->vehicle) {
  startRow();
}

// The first telemetry row fixes the references of dz_com_m and rack_m.
void CarCore::startRow() {
  scenario::TelemetryRowMaker::Values values;
  const vehicle::VehicleSample s = sim_->sample();
  rowMaker_.fill(s, {}, values);
}

void CarCore::reset() {
  sim_->restore(initial_);
  failure_.clear();
  last_ = {};
}

void CarCore::tick(const std::optional<scenario::DriverInput>& input) {
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

void CarCore::observation(double* out) {
  const vehicle::VehicleSample s = sim_->sample();
  const double values[kObservationSize] = {s.t,  s.com.x(), s.com.y(), s.yaw,   s.vx,    s.vy,
                                           s.yawRate, s.ax, s.ay, s.roll, s.pitch, s.speed,
                                           sim_->steerAt(s.t)};
  std::copy(values, values + kObservationSize, out);
}

void CarCore::telemetryRow(double* out) {
  const vehicle::VehicleSample s = sim_->sample();
  const scenario::DriverInput in = sim_->lastInput();
  scenario::TelemetryInputs ti{sim_->steerAt(s.t), in.throttle, in.brake, last_.iterations, last_.correction, 0,
                               fidelity(), sim_->takeSwitchJump(), sim_->powertrainChannels(), {}};
  scenario::TelemetryRowMaker::Values values;
  rowMaker_.fill(s, ti, values);
  std::copy(values.begin(), values.begin() + rowMaker_.columns(), out);
}

vehicle::VehicleView CarCore::view() {
  sim_->sample();
  return sim_->view();
}

vehicle::HudInfo CarCore::hud() {
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

std::vector<char> CarCore::save() { return sim_->saveBytes(); }

void CarCore::restore(const std::vector<char>& bytes) {
  sim_->restoreBytes(bytes);
  failure_.clear();
  last_ = {};
}

RunTelemetry runScenario(const std::string& scenarioPath, const app::ScenarioOverrides& overrides,
                         const std::string& csvPath) {
  const scenario::ScenarioSpec spec = app::loadScenario(scenarioPath, overrides);
  const std::vector<std::string> inputs{scenarioPath, spec.vehicleFile, spec.terrainFile};
  scenario::refuseOverwritingInputs(csvPath, inputs);
  scenario::Simulation sim(spec);
  scenario::refuseOverwritingInputs(csvPath, inputs);  // and the files the world read
  RunTelemetry out;
  scenario::TelemetryRowMaker maker(sim.world().vehicle);
  out.columns = maker.names();
  scenario::RunOptions opt;
  opt.telemetryPath = csvPath;
  opt.keepStepCost = false;
  opt.keepSamples = false;
  opt.onRow = [&](const vehicle::VehicleSample& s, const scenario::TelemetryInputs& in) {
    scenario::TelemetryRowMaker::Values v;
    maker.fill(s, in, v);
    out.rows.insert(out.rows.end(), v.begin(), v.begin() + maker.columns());
  };
  out.result = scenario::runScenario(sim, opt);
  return out;
}

}  // namespace bdfcar::api
