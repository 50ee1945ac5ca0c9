// `bdfcar drive [SCENARIO]`: drive with a wheel, game controller, joystick or
// the keyboard in a window; record the inputs, replay them (in the window or
// as a batch run) bit for bit.
#include <cstdio>
#include <memory>
#include <optional>

#include <cstdlib>
#include <filesystem>

#include "cli_errors.h"
#include "interrupt.h"
#include "scenario/row_file.h"
#include "commands.h"
#include "demo_common.h"
#include "interactive/drive_loop.h"
#include "scenario_overrides.h"
#include "session/drive_picks.h"

namespace bdfcar::app {

namespace {

// Where F9 keeps its recordings: $XDG_DATA_HOME/bdfcar/recordings, else
// ~/.local/share/bdfcar/recordings, else ./recordings.
std::string defaultRecordDir() {
  if (const char* x = std::getenv("XDG_DATA_HOME"); x && *x) return std::string(x) + "/bdfcar/recordings";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.local/share/bdfcar/recordings";
  return "recordings";
}

struct DriveArgs {
  std::string scenario = std::string(BDFCAR_ASSET_DIR) + "/scenarios/drive_powertrain.toml";
  std::string record, replay, telemetry, laps, screenshot, mappings, recordDir = defaultRecordDir(), size = "1280x720";
  double seconds = 0;
  int msaa = -1;  // --msaa; -1: automatic
  std::string renderScale = "auto";
  bool batch = false, noVsync = false, noSound = false, replayAnyway = false, scenarioGiven = false;
  ScenarioOverrides overrides;
};

// After a drive: the course's and the laps' results, its divergences, its
// outputs written and closed.
void finishDrive(DriveSession& session, const std::string& telemetry, const std::string& laps) {
  if (const auto c = session.courseResult()) {
    if (c->exitTime >= 0)
      std::printf("course: %s, course time %.2f s\n", scenario::courseVerdict(*c).c_str(), c->exitTime - c->entryTime);
    else
      std::printf("course: %s\n", scenario::courseVerdict(*c).c_str());
  }
  if (const scenario::LapTimer* l = session.laps()) {
    std::printf("%s", l->laps().empty() ? "laps: none completed\n" : scenario::lapsSummary(l->laps()).c_str());
    if (!laps.empty()) scenario::writeLapFile(laps, l->laps(), l->sectors());
  }
  if (session.resets() > 0)
    std::printf("%d divergence%s, each time back to the last good snapshot; the last: %s: %s\n", session.resets(),
                session.resets() == 1 ? "" : "s", session.notice().c_str(), session.lastDivergence().c_str());
  session.closeOutputs();
  if (!telemetry.empty()) std::printf("telemetry: %s (%d segment%s)\n", telemetry.c_str(), session.segment() + 1,
                                      session.segment() == 0 ? "" : "s");
}

int runDrive(const DriveArgs& a) {
  std::unique_ptr<Recording> replay;
  if (!a.replay.empty()) replay = std::make_unique<Recording>(readRecording(a.replay));
  if (replay && replay->droppedLine)
    std::fprintf(stderr, "%s:%d: the last line is cut off (no newline: the recording was stopped mid-line); "
                 "replaying the %ld whole ticks before it\n", a.replay.c_str(), replay->droppedLine, replay->inputCount());
  // A replay without a scenario on the command line replays against the one it names.
  std::string scenarioFile = a.scenario;
  if (replay && !a.scenarioGiven && !replay->scenarioFile.empty() && std::filesystem::is_regular_file(replay->scenarioFile))
    scenarioFile = replay->scenarioFile;
  scenario::ScenarioSpec spec = loadScenario(scenarioFile, a.overrides);
  if (replay && !a.replayAnyway) {
    const std::string why = replayMismatch(*replay, spec);
    if (!why.empty())
      throw std::runtime_error(a.replay + ": " + why + ": the replay would not reproduce the drive (--replay-anyway replays it all the same)");
  }
  if (!a.laps.empty() && !spec.laps.enabled)
    throw std::runtime_error("--laps " + a.laps + ": " + scenarioFile + " times no laps (it has no [laps] table)");
  scenario::refuseSameOutputs({{"--telemetry", a.telemetry}, {"--record", a.record}, {"--laps", a.laps}});
  for (const std::string& out : {a.telemetry, a.record, a.laps})
    scenario::refuseOverwritingInputs(out, {scenarioFile, spec.vehicleFile, spec.terrainFile, a.replay});
  InterruptGuard interrupts;
  SessionOptions so;
  so.telemetryPath = a.telemetry;
  so.recordPath = a.record;
  so.rewindable = true;  // rewind, and a divergence goes back to the last good snapshot
  auto session = std::make_unique<DriveSession>(spec, so);
  std::string lapsPath = a.laps;
  if (replay && a.batch) {
    // As fast as possible, no window: the same inputs give the same bits.
    for (const RecordedTick& e : replay->entries)
      if (interruptRequested() || !session->replay(e)) break;
    std::printf("replayed %ld ticks to t = %.3f s (%d steps of %g s per %g ms tick)\n", replay->inputCount(),
                session->time(), session->simulation().stepsPerTick(), spec.integrator.step, spec.tick * 1e3);
  } else {
    InteractiveOptions io;
    io.driver = replay ? DriverSource::Replay : DriverSource::Person;
    io.replay = replay.get();
    io.mappingDir = a.mappings;
    io.recordDir = a.recordDir;
    io.seconds = a.seconds;
    io.vsync = !a.noVsync;
    io.multisample = a.msaa;
    io.renderScale = a.renderScale == "auto" ? 0.0 : std::stod(a.renderScale);
    io.sound = !a.noSound;
    io.screenshot = a.screenshot;
    if (!parseSize(a.size, io.width, io.height)) throw std::runtime_error("--size: expected WIDTHxHEIGHT");
    for (int drive = 1;; ++drive) {
      DrivePicks picks;
      if (!replay) picks = drivePicks(spec);  // a replay drives the recording's car
      io.picks = picks.menu;
      std::optional<MenuChoice> again;
      const LoopStats stats = runInteractive(*session, io, &again);
      std::printf("%s\n", stats.summary().c_str());
      if (!again || interruptRequested()) break;
      // "Drive them here": the chosen car on the chosen rung, at the place
      // the drive was at, in outputs of its own; a car that cannot be driven
      // is said and the drive goes on with the car it had.
      ScenarioOverrides o = a.overrides;
      o.vehicle = picks.carFiles[again->car];
      o.fidelity = picks.menu.fidelities[again->fidelity];
      const int place = session->place();
      SessionOptions next = so;
      next.telemetryPath = driveOutput(a.telemetry, drive + 1);
      next.recordPath = driveOutput(a.record, drive + 1);
      scenario::ScenarioSpec nextSpec;
      std::unique_ptr<DriveSession> nextSession;
      try {
        nextSpec = loadScenario(scenarioFile, o);
        nextSession = std::make_unique<DriveSession>(nextSpec, next);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s: %s; driving on with %s\n", o.vehicle->c_str(), e.what(),
                     spec.vehicleFile.c_str());
        io.startMessage = std::string("cannot drive ") + picks.menu.cars[again->car] + ": " + e.what();
        continue;
      }
      if (place >= 0 && !nextSession->goTo(place))
        io.startMessage = nextSession->placeNotice();
      else
        io.startMessage = picks.menu.cars[again->car] + " on the " + *o.fidelity + " model";
      finishDrive(*session, so.telemetryPath, lapsPath);  // a write error here ends the drive, as at its end
      session = std::move(nextSession);
      spec = std::move(nextSpec);
      so = next;
      lapsPath = driveOutput(a.laps, drive + 1);
      std::printf("driving %s (%s) on the %s model%s%s\n", picks.menu.cars[again->car].c_str(), o.vehicle->c_str(),
                  o.fidelity->c_str(), so.telemetryPath.empty() ? "" : "; telemetry: ", so.telemetryPath.c_str());
    }
  }
  finishDrive(*session, so.telemetryPath, lapsPath);
  if (interruptRequested()) {
    std::fprintf(stderr, "stopped by %s at t = %.3f s\n", interruptSignalName(), session->time());
    return interruptExitStatus();
  }
  if (session->failed()) {
    std::fprintf(stderr, "error: %s\n", session->failure().c_str());
    return 3;
  }
  return 0;
}

}  // namespace

void addDriveCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand("drive", "Drive a scenario in a window with a wheel, controller, joystick or keyboard");
  auto a = std::make_shared<DriveArgs>();
  cmd->add_option("scenario", a->scenario,
                  "Scenario file (default: the drivable sedan at a standstill on the proving ground's circuit; with --replay, the recording's)")
      ->check(CLI::ExistingFile)
      ->each([a](const std::string&) { a->scenarioGiven = true; });
  cmd->add_option("--record", a->record, "Record the inputs of every tick to this file");
  cmd->add_option("--replay", a->replay, "Replay recorded inputs instead of the devices")->check(CLI::ExistingFile);
  cmd->add_flag("--batch", a->batch, "With --replay: no window, as fast as possible");
  cmd->add_flag("--replay-anyway", a->replayAnyway,
                "Replay a recording made with another scenario, vehicle or tick (it will not reproduce the drive)");
  cmd->add_option("--record-dir", a->recordDir, "Folder of the recordings F9 starts (default: " + defaultRecordDir() + ")");
  cmd->add_option("--telemetry", a->telemetry, "Write telemetry CSV while driving");
  cmd->add_option("--laps", a->laps,
                  "A scenario that times laps ([laps]; the default one does): write the laps here at the end, one CSV "
                  "row each (docs/SCENARIOS.md)");
  cmd->add_option("--seconds", a->seconds, "Stop after this much wall time")->check(CLI::Range(0.0, 1e6));
  cmd->add_option("--size", a->size, "Window size, e.g. 1280x720");
  cmd->add_flag("--no-vsync", a->noVsync, "Do not wait for the display's refresh");
  cmd->add_option("--msaa", a->msaa,
                  "Multisampling (anti-aliasing) samples, 0 for none; default: 4 on a GPU, none on software GL (where "
                  "each sample costs as much as a frame)")
      ->check(CLI::Range(0, 16));
  cmd->add_option("--render-scale", a->renderScale,
                  "Resolution of the 3D view, of the window's width and height (the HUD stays sharp): 0.5 to 1, or "
                  "auto (default): on a GPU lowered in steps while frames take longer than 1/30 s and raised again "
                  "when they would not; on software GL full (stretching costs it what it saves)")
      ->check(CLI::IsMember({"auto"}) | CLI::Range(0.5, 1.0));
  cmd->add_flag("--no-sound", a->noSound, "No engine, tyre or wind sound (default: played on the default sound device)");
  cmd->add_option("--screenshot", a->screenshot, "Save the last frame as PNG");
  cmd->add_option("--mappings", a->mappings, "Folder of input mapping files (*.toml; default: the shipped ones)")
      ->check(CLI::ExistingDirectory);
  addOverrideOptions(*cmd, a->overrides);
  commands.push_back({cmd, [a] { return reportErrors([&] { return runDrive(*a); }); }});
}

}  // namespace bdfcar::app
