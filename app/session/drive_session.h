// One drive: a scenario run through the shared run driver (scenario/run.h)
// with a driver's input tick by tick (a person's, the scenario's scripted
// driver, or a replay), plus what only a drive has: the input recording,
// restart and rewind as recorded events, and the HUD figures. No window, no
// devices: the interactive loop, the headless renderer, the demo and the
// tests all drive through this.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "scenario/run.h"
#include "session/input_recording.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::app {

struct SessionOptions {
  std::string telemetryPath;   // empty: none
  std::string recordPath;      // empty: no input recording
  // A person's drive: snapshots for rewind, and a divergence goes back to the
  // last good snapshot (with a message) instead of ending the drive.
  bool rewindable = false;
};

enum class DriverSource { Person, Scripted, Replay };

class DriveSession {
 public:
  // Builds the world once and prepares the run; throws when the vehicle
  // cannot be assembled or settled.
  DriveSession(const scenario::ScenarioSpec& spec, const SessionOptions& options);
  ~DriveSession();

  // Back to the start of the scenario (an assignment of the initial state);
  // recorded as an event. Telemetry goes on in the same file.
  void restart();
  // One snapshot (0.5 s) back; recorded. False when there is nothing to go back to.
  bool rewind();
  // Restarts the drive at the scenario's place `place` (ScenarioSpec::places:
  // the menu's "go to"), recorded as an event; restart() then comes back
  // there. False when there is no such place or the car cannot start there
  // (placeNotice() says why; the drive goes on as it was).
  bool goTo(int place);
  const std::string& placeNotice() const { return notice_; }
  int place() const { return place_; }  // -1: the scenario's [start]
  // Restarts the scenario recording every tick's input to `path` (a new file:
  // a recording replays from the scenario's start).
  void startRecording(const std::string& path);
  // Closes the recording (throws scenario::OutputError when it cannot be
  // written); returns the ticks it holds.
  long stopRecording();
  bool recording() const { return recorder_ != nullptr; }
  const std::string& recordingPath() const { return options_.recordPath; }
  // Writes out and closes the telemetry and the recording; throws
  // scenario::OutputError on a write error (a full disk).
  void closeOutputs();
  // The telemetry segment (a column): +1 at each restart, rewind and divergence reset.
  int segment() const { return run_->segment(); }
  // One driver tick: the given input (a person's, or a replay's) or, with
  // nullopt, the scenario's own driver. Returns false once the run failed
  // (a non-rewindable run diverged): failure() says why.
  bool tick(const std::optional<scenario::DriverInput>& input);
  // A recording's line: an input tick, or a reset / rewind event.
  bool replay(const RecordedTick& entry);

  bool failed() const { return run_->failed(); }
  std::string failure() const { return run_->failureText(); }
  // The last divergence absorbed by going back to a snapshot ("" if none).
  const std::string& notice() const { return run_->notice(); }
  const std::string& lastDivergence() const { return run_->lastDivergence(); }
  int resets() const { return run_->resets(); }
  double time() const { return sim_->time(); }
  long ticks() const { return run_->ticks(); }
  bool finished() const { return run_->finished(); }
  // The lap timing of a scenario with [laps] (nullptr without).
  const scenario::LapTimer* laps() const { return run_->laps(); }

  // The latest state for drawing and the HUD (computes a sample).
  vehicle::VehicleView view();
  vehicle::HudInfo hud(double realTimeFactor, double stepSeconds, const std::string& message);
  const vehicle::VehicleSample& lastSample() const { return sample_; }
  std::optional<scenario::CourseResult> courseResult() const { return run_->course(); }
  // Normalised steering torque for force feedback: the rack force over the
  // force at which the driver feels the full torque.
  double steeringFeel() const;

  scenario::Simulation& simulation() { return *sim_; }
  const scenario::Simulation& simulation() const { return *sim_; }
  const scenario::ScenarioSpec& spec() const { return sim_->spec(); }

 private:
  SessionOptions options_;
  std::unique_ptr<scenario::Simulation> sim_;
  std::unique_ptr<scenario::Run> run_;
  std::unique_ptr<InputRecorder> recorder_;
  int place_ = -1;          // where the drive restarted last (-1: the scenario's [start])
  std::string notice_;      // why the last goTo failed
  vehicle::VehicleSample sample_;
};

}  // namespace bdfcar::app
