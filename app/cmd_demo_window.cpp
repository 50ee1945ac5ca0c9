// `bdfcar demo`: the ISO 3888-1 lane change driven by the path follower, on
// screen when a display is reachable, otherwise handed to bdfcar-headless
// (frames, video, telemetry, plots).
#include <cstdio>
#include <memory>

#include "cli_errors.h"
#include "commands.h"
#include "demo_common.h"
#include "interactive/drive_loop.h"
#include "process.h"
#include "render/frame.h"

namespace bdfcar::app {

namespace {

int runDemo(const DemoOptions& o) {
  if (!o.headless && displayConfigured()) {
    scenario::ScenarioSpec spec = scenario::loadScenarioFile(o.scenario);
    SessionOptions so;
    so.telemetryPath = demoTelemetryPath(o);
    DriveSession session(spec, so);
    InteractiveOptions io;
    io.driver = DriverSource::Scripted;
    io.quitAtEnd = true;
    io.width = o.width;
    io.height = o.height;
    try {
      const LoopStats stats = runInteractive(session, io);
      std::printf("%s\n", stats.summary().c_str());
      return finishDemo(session, o);
    } catch (const render::RenderError& e) {
      std::fprintf(stderr, "note: no usable display (%s): rendering headless instead\n", e.what());
    }
  } else if (!o.headless) {
    std::fprintf(stderr, "note: no display (DISPLAY unset): rendering headless\n");
  }
  const std::string why = execHeadless();
  std::fprintf(stderr, "error: %s\n", why.c_str());
  return 1;
}

}  // namespace

void addDemoCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "demo", "The ISO 3888-1 double lane change by the path-following driver: on screen, or frames + video + "
              "telemetry + plots without a display");
  auto o = std::make_shared<DemoOptions>();
  addDemoOptions(*cmd, *o);
  cmd->add_flag("--headless", o->headless, "Render frames even when a display is available");
  commands.push_back({cmd, [o] { return reportErrors([&] { return runDemo(*o); }); }});
}

void addRenderDelegateCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scenario to PNG frames (and a video) without a display");
  cmd->allow_extras();
  cmd->prefix_command();
  cmd->set_help_flag();  // --help too goes to bdfcar-headless, which has the options to list
  commands.push_back({cmd, [] {
                        const std::string why = execHeadless();
                        std::fprintf(stderr, "error: %s\n", why.c_str());
                        return 1;
                      }});
}

}  // namespace bdfcar::app
