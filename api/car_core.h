// The car behind the library's API (include/bdfcar/bdfcar.h wraps it; the
// Python module binds it): a scenario's simulation stepped tick by tick
// with a person's (an agent's) input or the scenario's own driver, its state
// as bytes, its observation and telemetry row as numbers; and a whole
// scenario run as `bdfcar run` runs it, its telemetry kept. Plain C++ on
// the internal headers, so that Python can step many cars on worker threads
// with the interpreter's lock released.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenario/run.h"
#include "scenario/simulation.h"
#include "scenario/telemetry_row.h"
#include "scenario_overrides.h"

namespace bdfcar::api {

// A step that failed (diverged, a state check): the car must be reset or
// restored before it steps again.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The overrides of a scenario's settings (as `bdfcar run`'s options);
// throws config::ConfigError for an unknown fidelity.
app::ScenarioOverrides carOverrides(const std::optional<std::string>& vehicle, const std::optional<std::string>& fidelity,
                                    std::optional<double> step, std::optional<double> duration,
                                    const std::vector<std::string>& settings);
// A driver's input, clamped to its ranges; throws std::invalid_argument for NaN or infinity.
scenario::DriverInput driverInput(double steer, double throttle, double brake);

// The compact observation (observationNames()): chassis pose, velocities,
// accelerations and the steering input, SI units.
constexpr int kObservationSize = 13;
const std::vector<std::string>& observationNames();

class CarCore {
 public:
  // Loads the scenario (with the overrides: vehicle, fidelity, step,
  // duration, --set settings), builds its world, settles the car.
  // sceneOf: joins that car's scene (its ground, built once) instead of
  // building one; the scenario must name the same ground.
  CarCore(const std::string& scenarioPath, const app::ScenarioOverrides& overrides, const CarCore* sceneOf = nullptr);
  // Another car in the same world (terrain and vehicle built once, shared
  // read-only), settled the same way: the state of `other` at its start.
  explicit CarCore(const CarCore& other);

  // Back to the state after settling (the start of the manoeuvre).
  void reset();
  // One driver tick: the given input (clamped to its range: steer [-1, 1],
  // throttle and brake [0, 1]) or, with nullopt, the scenario's own driver.
  // Throws SimulationError (and stays failed) when a step fails.
  void tick(const std::optional<scenario::DriverInput>& input);
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }

  double time() const { return sim_->time(); }
  double duration() const { return sim_->spec().duration; }
  double tickSeconds() const { return sim_->spec().tick; }
  int stepsPerTick() const { return sim_->stepsPerTick(); }
  // The fidelity rung driving now (vehicle::Fidelity: 0 linkage, 1 kinematic, 2 planar).
  int fidelity() const { return static_cast<int>(sim_->vehicle().fidelity); }
  const scenario::Simulation& simulation() const { return *sim_; }
  scenario::Simulation& simulation() { return *sim_; }
  // What a frame draws: the poses now, and the HUD's figures.
  vehicle::VehicleView view();
  vehicle::HudInfo hud();

  // The observation of the current state (kObservationSize values).
  void observation(double* out);
  // The telemetry row of the current state, as the CSV would print it
  // (TelemetryRowMaker; the references of dz_com_m and rack_m are the
  // start's).
  int telemetryColumns() const { return rowMaker_.columns(); }
  std::vector<std::string> telemetryNames() const { return rowMaker_.names(); }
  void telemetryRow(double* out);

  std::vector<char> save();
  // Throws scenario::RunStateBytesError (bytes of another car, corrupted...).
  void restore(const std::vector<char>& bytes);

 private:
  void startRow();

  std::shared_ptr<const scenario::World> world_;
  std::unique_ptr<scenario::Simulation> sim_;
  scenario::RunState initial_;
  scenario::TelemetryRowMaker rowMaker_;
  integ::StepReport last_;
  std::string failure_;
};

// A whole scenario with its own driver, as `bdfcar run` runs it: the
// telemetry rows (columns x rows, row after row) and, with csvPath, the
// command's file byte for byte. A failed run is a result; bad files throw.
struct RunTelemetry {
  std::vector<std::string> columns;
  std::vector<double> rows;
  scenario::RunResult result;
};
RunTelemetry runScenario(const std::string& scenarioPath, const app::ScenarioOverrides& overrides,
                         const std::string& csvPath = "");

}  // namespace bdfcar::api
