// The demo (the README's main job): the ISO 3888-1 double lane change driven
// by the path follower, with telemetry, plots and the course verdict,
// on screen (bdfcar) or as frames and a video (bdfcar-headless).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "session/drive_session.h"

namespace bdfcar::app {

struct DemoOptions {
  std::string scenario = std::string(BDFCAR_ASSET_DIR) + "/scenarios/iso_lane_change.toml";
  std::string outDir = "out/demo";
  bool headless = false;   // bdfcar: render headless even with a display
  double fps = 30;
  int width = 1280, height = 720;
  bool frames = true;            // headless: PNG frames beside the video (--no-frames: video only)
  std::string camera = "chase";  // headless: the camera the frames are drawn from
};

void addDemoOptions(CLI::App& cmd, DemoOptions& o);
// Telemetry path inside the output folder.
std::string demoTelemetryPath(const DemoOptions& o);
// After the run: plots, the verdict on the console; exit code (0 passed,
// 4 course failed, 3 diverged).
int finishDemo(DriveSession& session, const DemoOptions& o);

// The course's verdict as one line ("ISO 3888-1 at 60 km/h: PASSED, 0 cones
// hit, peak a_y ..."), "" without a course: the demo's closing card and its
// last line on stdout.
std::string courseVerdictLine(const DriveSession& session);
// Parses "1280x720".
bool parseSize(const std::string& text, int& width, int& height);

}  // namespace bdfcar::app
