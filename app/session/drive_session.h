// One drive: a scenario's simulation advanced tick by tick with a driver's
// input (a person's, the scenario's scripted driver, or a replay), with
// telemetry, input recording, the course judge and the HUD figures. No
// window, no devices: the interactive loop, the headless renderer, the demo
// and the tests all drive through this.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "scenario/course_judge.h"
#include "scenario/simulation.h"
#include "scenario/telemetry.h"
#include "session/input_recording.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::app {

struct SessionOptions {
  std::string telemetryPath;   // empty: none
  std::string recordPath;      // empty: no input recording
};

enum class DriverSource { Person, Scripted, Replay };

class DriveSession {
 public:
  DriveSession(const scenario::ScenarioSpec& spec, const SessionOptions& options);
  // Back to the start of the scenario (static equilibrium, speed, settling).
  void restart();
  // Restarts the scenario recording every tick's input to `path`.
  void startRecording(const std::string& path);
  const std::string& recordingPath() const { return options_.recordPath; }
  // One physics tick: the given input (a person's, or a replay's) or, with
  // nullopt, the scenario's own driver. Returns false once the run failed
  // (diverged): failure() says why.
  bool tick(const std::optional<scenario::DriverInput>& input);
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }
  double time() const { return sim_->time(); }
  long ticks() const { return ticks_; }
  bool finished() const { return time() >= spec_.duration - 1e-9; }

  // The latest state for drawing and the HUD (computes a sample).
  vehicle::VehicleView view();
  vehicle::HudInfo hud(double realTimeFactor, double stepSeconds, const std::string& message);
  const vehicle::VehicleSample& lastSample() const { return sample_; }
  const std::optional<scenario::CourseResult> courseResult() const;
  // Normalised steering torque for force feedback: the rack force over the
  // force at which the driver feels the full torque.
  double steeringFeel() const;

  scenario::Simulation& simulation() { return *sim_; }
  const scenario::ScenarioSpec& spec() const { return spec_; }

 private:
  void record();

  scenario::ScenarioSpec spec_;
  SessionOptions options_;
  std::unique_ptr<scenario::Simulation> sim_;
  std::unique_ptr<scenario::TelemetryWriter> telemetry_;
  std::unique_ptr<InputRecorder> recorder_;
  std::optional<scenario::CourseJudge> judge_;
  vehicle::VehicleSample sample_;
  std::string failure_;
  long ticks_ = 0;
  long outputEvery_ = 1;
  int lastIterations_ = 0;
  double lastCorrection_ = 0;
};

}  // namespace bdfcar::app
