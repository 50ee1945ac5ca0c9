// bdfcar-headless's commands: `render SCENARIO --out DIR` and `demo`
// (OSMesa, no display server).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli_errors.h"
#include "interrupt.h"
#include "scenario/row_file.h"
#include "commands.h"
#include "demo_common.h"
#include "headless/frames.h"
#include "scenario_overrides.h"

namespace bdfcar::app {

namespace {

bool ffmpegAvailable() { return std::system("command -v ffmpeg > /dev/null 2>&1") == 0; }

void printFrameStats(const FramesResult& r) {
  const Percentiles rp = r.stats.render();
  std::printf("%d frames %dx%d (%s): render p50 %.1f ms, p99 %.1f ms", r.frames, r.width, r.height, r.renderer.c_str(),
              1e3 * rp.p50, 1e3 * rp.p99);
  std::printf("; drawn p50 %lu triangles in %u drawables", r.drawnP50.triangles, r.drawnP50.drawables);
  if (r.pngEncode.p50 > 0)
    std::printf("; PNG encode p50 %.1f ms, p99 %.1f ms (worker thread)", 1e3 * r.pngEncode.p50, 1e3 * r.pngEncode.p99);
  // The whole pipeline: what a frame costs once encoding is paid for too.
  std::printf("; %.1f ms a frame end to end (%.2f s), the loop waited %.2f s in all for output\n",
              r.frames > 0 ? 1e3 * r.wallSeconds / r.frames : 0.0, r.wallSeconds, r.encodeSeconds);
}

struct RenderArgs {
  std::string scenario, outDir, video, size = "1280x720", camera = "chase", body = "solid", telemetry, wav, place;
  double fps = 30;
  bool noFrames = false;  // no PNG: the raw frames go to ffmpeg (--video), or nowhere (timing the drawing)
  ScenarioOverrides overrides;
};

// The scenario's [[places]] entry that `wanted` names (its name, or its number
// from 1), or nothing.
const scenario::Place* findPlace(const scenario::ScenarioSpec& spec, const std::string& wanted) {
  for (std::size_t i = 0; i < spec.places.size(); ++i)
    if (spec.places[i].name == wanted || std::to_string(i + 1) == wanted) return &spec.places[i];
  return nullptr;
}

int runRender(const RenderArgs& a) {
  if (!a.noFrames && a.outDir.empty()) {
    std::fprintf(stderr, "error: give --out DIR for the frames (or --no-frames, with --video FILE or alone)\n");
    return kExitUsage;
  }
  scenario::ScenarioSpec spec = loadScenario(a.scenario, a.overrides);
  if (!a.place.empty()) {
    const scenario::Place* place = findPlace(spec, a.place);
    if (!place) {
      std::string names;
      for (std::size_t i = 0; i < spec.places.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i + 1) + " '" + spec.places[i].name + "'";
      std::fprintf(stderr, "error: --place: %s has no place '%s'; expected the name or number of one of its [[places]]%s\n",
                   a.scenario.c_str(), a.place.c_str(), names.empty() ? " (it has none)" : (": " + names).c_str());
      return kExitUsage;
    }
    spec.startX = place->x;
    spec.startY = place->y;
    spec.startHeading = place->heading;
  }
  FramesOptions fo;
  fo.outDir = a.noFrames ? "" : a.outDir;
  fo.video = a.video;
  fo.fps = a.fps;
  fo.camera = a.camera;
  fo.body = a.body;
  fo.wav = a.wav;
  if (!parseSize(a.size, fo.width, fo.height)) throw std::runtime_error("--size: expected WIDTHxHEIGHT, e.g. 1280x720");
  scenario::refuseSameOutputs({{"--telemetry", a.telemetry}, {"--wav", a.wav}, {"--video", a.video}});
  for (const std::string& out : {a.telemetry, a.wav, a.video})
    scenario::refuseOverwritingInputs(out, {a.scenario, spec.vehicleFile, spec.terrainFile});
  InterruptGuard interrupts;
  SessionOptions so;
  so.telemetryPath = a.telemetry;
  DriveSession session(spec, so);
  const FramesResult r = renderFrames(session, fo);
  session.closeOutputs();
  printFrameStats(r);
  if (!fo.wav.empty())
    std::printf("sound: %s (%.2f s at 48 kHz)\n", fo.wav.c_str(), static_cast<double>(r.soundFrames) / 48000.0);
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

int runHeadlessDemo(const DemoOptions& o) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(o.scenario);
  SessionOptions so;
  so.telemetryPath = demoTelemetryPath(o);
  InterruptGuard interrupts;
  DriveSession session(spec, so);
  FramesOptions fo;
  fo.outDir = o.frames ? (std::filesystem::path(o.outDir) / "frames").string() : "";
  fo.fps = o.fps;
  fo.width = o.width;
  fo.height = o.height;
  fo.camera = o.camera;
  if (ffmpegAvailable()) {
    fo.video = (std::filesystem::path(o.outDir) / "demo.mp4").string();
  } else if (!o.frames) {
    std::fprintf(stderr, "error: --no-frames needs ffmpeg for the video, and ffmpeg is not installed\n");
    return kExitUsage;
  } else {
    std::fprintf(stderr, "note: ffmpeg is not installed: frames only, no video\n");
  }
  const FramesResult r = renderFrames(session, fo);
  session.closeOutputs();
  printFrameStats(r);
  if (interruptRequested()) {
    std::fprintf(stderr, "stopped by %s at t = %.3f s\n", interruptSignalName(), session.time());
    return interruptExitStatus();
  }
  if (!fo.outDir.empty()) std::printf("frames: %s/frame_*.png\n", fo.outDir.c_str());
  if (!fo.video.empty()) std::printf("video: %s\n", fo.video.c_str());
  return finishDemo(session, o);
}

}  // namespace

void addHeadlessCommands(CLI::App& app, CommandList& commands) {
  {
    CLI::App* cmd = app.add_subcommand("render", "Render a scenario to PNG frames and/or a video with OSMesa");
    auto a = std::make_shared<RenderArgs>();
    cmd->add_option("scenario", a->scenario, "Scenario file")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out,-o", a->outDir, "Folder for frame_NNNNN.png (not with --no-frames)");
    cmd->add_flag("--no-frames", a->noFrames,
                  "No PNG is encoded or written: with --video the raw frames are piped to ffmpeg; alone, the frames "
                  "are only drawn (their timing is printed: the frame rate without encoding)");
    cmd->add_option("--place", a->place,
                    "Start at one of the scenario's [[places]] (its name or number from 1), e.g. --place 'rough road'");
    cmd->add_option("--fps", a->fps, "Frames per second of simulated time")->check(CLI::Range(1.0, 240.0));
    cmd->add_option("--size", a->size, "Frame size, e.g. 1280x720");
    cmd->add_option("--video", a->video, "Also write a video (through ffmpeg), e.g. run.mp4");
    cmd->add_option("--camera", a->camera, "chase, hood, orbit or top-down")
        ->check(CLI::IsMember({"chase", "hood", "orbit", "top-down"}));
    cmd->add_option("--body", a->body,
                    "solid, translucent or hidden: the last two show the suspension view, what the running model "
                    "has (the linkage's members, the kinematic corners' springs, the planar body's posts)")
        ->check(CLI::IsMember({"solid", "translucent", "hidden"}));
    cmd->add_option("--telemetry", a->telemetry, "Also write the telemetry CSV");
    cmd->add_option("--wav", a->wav,
                    "Also write the car's sound (engine, tyres, wind, shifts, bumps; as `drive` plays it) as a WAV "
                    "file, 48 kHz mono: the soundtrack, tested without a sound card");
    addOverrideOptions(*cmd, a->overrides);
    commands.push_back({cmd, [a] { return reportErrors([&] { return runRender(*a); }); }});
  }
  {
    CLI::App* cmd = app.add_subcommand("demo", "The ISO 3888-1 lane change demo as frames, video, telemetry and plots");
    auto o = std::make_shared<DemoOptions>();
    addDemoOptions(*cmd, *o);
    cmd->add_flag("--headless", o->headless, "(always headless here)");
    commands.push_back({cmd, [o] { return reportErrors([&] { return runHeadlessDemo(*o); }); }});
  }
}

}  // namespace bdfcar::app
