// `bdfcar drive [SCENARIO]`: drive with a wheel, game controller, joystick or
// the keyboard in a window; record the inputs, replay them (in the window or
// as a batch run) bit for bit.
#include <cstdio>
#include <memory>

#include <cstdlib>
#include <filesystem>

#include "cli_errors.h"
#include "interrupt.h"
#include "scenario/row_file.h"
#include "commands.h"
#include "demo_common.h"
#include "interactive/drive_loop.h"
#include "scenario_overrides.h"

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
  bool batch = false, noVsync = false, noSound = false, replayAnyway = false, scenarioGiven = false;
  ScenarioOverrides overrides;
};

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
  DriveSession session(spec, so);
  if (replay && a.batch) {
    // As fast as possible, no window: the same inputs give the same bits.
    for (const RecordedTick& e : replay->entries)
      if (interruptRequested() || !session.replay(e)) break;
    std::printf("replayed %ld ticks to t = %.3f s (%d steps of %g s per %g ms tick)\n", replay->inputCount(),
                session.time(), session.simulation().stepsPerTick(), spec.integrator.step, spec.tick * 1e3);
  } else {
    InteractiveOptions io;
    io.driver = replay ? DriverSource::Replay : DriverSource::Person;
    io.replay = replay.get();
    io.mappingDir = a.mappings;
    io.recordDir = a.recordDir;
    io.seconds = a.seconds;
    io.vsync = !a.noVsync;
    io.multisample = a.msaa;
    io.sound = !a.noSound;
    io.screenshot = a.screenshot;
    if (!parseSize(a.size, io.width, io.height)) throw std::runtime_error("--size: expected WIDTHxHEIGHT");
    const LoopStats stats = runInteractive(session, io);
    std::printf("%s\n", stats.summary().c_str());
  }
  if (const auto c = session.courseResult()) {
    if (c->exitTime >= 0)
      std::printf("course: %s, course time %.2f s\n", scenario::courseVerdict(*c).c_str(), c->exitTime - c->entryTime);
    else
      std::printf("course: %s\n", scenario::courseVerdict(*c).c_str());
  }
  if (const scenario::LapTimer* l = session.laps()) {
    std::printf("%s", l->laps().empty() ? "laps: none completed\n" : scenario::lapsSummary(l->laps()).c_str());
    if (!a.laps.empty()) scenario::writeLapFile(a.laps, l->laps(), l->sectors());
  }
  if (session.resets() > 0)
    std::printf("%d divergence%s, each time back to the last good snapshot; the last: %s: %s\n", session.resets(),
                session.resets() == 1 ? "" : "s", session.notice().c_str(), session.lastDivergence().c_str());
  session.closeOutputs();
  if (!a.telemetry.empty()) std::printf("telemetry: %s (%d segment%s)\n", a.telemetry.c_str(), session.segment() + 1,
                                        session.segment() == 0 ? "" : "s");
  if (interruptRequested()) {
    std::fprintf(stderr, "stopped by %s at t = %.3f s\n", interruptSignalName(), session.time());
    return interruptExitStatus();
  }
  if (session.failed()) {
    std::fprintf(stderr, "error: %s\n", session.failure().c_str());
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
  cmd->add_flag("--no-sound", a->noSound, "No engine, tyre or wind sound (default: played on the default sound device)");
  cmd->add_option("--screenshot", a->screenshot, "Save the last frame as PNG");
  cmd->add_option("--mappings", a->mappings, "Folder of input mapping files (*.toml; default: the shipped ones)")
      ->check(CLI::ExistingDirectory);
  addOverrideOptions(*cmd, a->overrides);
  commands.push_back({cmd, [a] { return reportErrors([&] { return runDrive(*a); }); }});
}

}  // namespace bdfcar::app
