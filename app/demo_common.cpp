#include "demo_common.h"

#include <cstdio>
#include <filesystem>

#include "session/plots.h"

namespace bdfcar::app {

bool parseSize(const std::string& text, int& w, int& h) {
  return std::sscanf(text.c_str(), "%dx%d", &w, &h) == 2 && w >= 16 && h >= 16 && w <= 7680 && h <= 4320;
}

void addDemoOptions(CLI::App& cmd, DemoOptions& o) {
  cmd.add_option("--scenario", o.scenario, "Scenario to demonstrate")->check(CLI::ExistingFile);
  cmd.add_option("--out,-o", o.outDir, "Output folder (telemetry, plots, frames, video)");
  cmd.add_option("--fps", o.fps, "Frames per second of the headless frames")->check(CLI::Range(1.0, 240.0));
  cmd.add_option_function<std::string>(
      "--size",
      [&o](const std::string& s) {
        if (!parseSize(s, o.width, o.height)) throw CLI::ValidationError("--size", "expected WIDTHxHEIGHT, e.g. 1280x720");
      },
      "Frame size, e.g. 1280x720");
  cmd.add_flag("--no-frames{false}", o.frames,
               "Headless: the video only (raw frames piped to ffmpeg), no PNG frames");
  cmd.add_option("--camera", o.camera, "Headless: the camera of the frames and video (chase, hood, orbit, top-down)")
      ->check(CLI::IsMember({"chase", "hood", "orbit", "top-down"}));
}

std::string demoTelemetryPath(const DemoOptions& o) {
  std::filesystem::create_directories(o.outDir);
  return (std::filesystem::path(o.outDir) / "telemetry.csv").string();
}

int finishDemo(DriveSession& session, const DemoOptions& o) {
  session.closeOutputs();  // the plots read the whole telemetry
  const std::string telemetry = demoTelemetryPath(o);
  const std::string why = plotDrive(telemetry, o.outDir, session.simulation().course(), session.spec().name);
  if (!why.empty()) std::fprintf(stderr, "note: %s\n", why.c_str());
  std::printf("telemetry: %s\n", telemetry.c_str());
  if (why.empty())
    std::printf("plots: %s/path.png, %s/lateral_acceleration.png\n", o.outDir.c_str(), o.outDir.c_str());
  if (session.failed()) {
    std::fprintf(stderr, "error: %s\n", session.failure().c_str());
    return 3;
  }
  if (const auto c = session.courseResult()) {
    const bool done = c->exitTime >= 0;
    std::printf("%s\n", courseVerdictLine(session).c_str());
    return c->passed && done ? 0 : 4;
  }
  return 0;
}

std::string courseVerdictLine(const DriveSession& session) {
  const auto c = session.courseResult();
  if (!c) return "";
  char line[256];
  std::snprintf(line, sizeof line, "ISO 3888-%d at %.0f km/h: %s, peak a_y %.2f m/s^2 (%.2f g)",
                session.spec().course.part, session.spec().speedControl.profile.target * 3.6,
                scenario::courseVerdict(*c).c_str(), c->peakLateralAcceleration, c->peakLateralAcceleration / 9.81);
  return line;
}

}  // namespace bdfcar::app
