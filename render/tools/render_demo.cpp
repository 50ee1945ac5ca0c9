// bdfcar-render-demo: renders the synthetic ISO 3888-1 lane change headless
// (OSMesa, no display) to PNG files and/or a video, to look at the scene.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "render/headless.h"
#include "render/png_queue.h"
#include "render/synthetic_drive.h"
#include "render/video_pipe.h"

using namespace bdfcar;

// Scene config of the demo: a two-lane road on a plane and the course in the right lane.
render::SceneConfig demoScene(const scenario::Iso3888Course& course) {
  render::SceneConfig cfg;
  cfg.terrain.name = "flat";
  cfg.terrain.road.present = true;
  cfg.terrain.road.startX = -100;
  cfg.terrain.road.endX = 400;
  cfg.terrain.road.centreY = 0.0;
  cfg.course = course;
  cfg.geometry.bodyMesh = "assets/models/sedan_body.obj";
  return cfg;
}

int main(int argc, char** argv) {
  CLI::App app{"Render the synthetic lane change headless (OSMesa) to PNG and/or video"};
  std::string outDir = "render-demo", video, camera = "chase", body = "solid";
  int width = 1280, height = 720, every = 10, pngLevel = 1;
  double fps = 50, from = 0, to = -1;
  app.add_option("--out", outDir, "folder for PNG files (empty: none)");
  app.add_option("--video", video, "also write this video file (ffmpeg)");
  app.add_option("--width", width);
  app.add_option("--height", height);
  app.add_option("--fps", fps, "frames per simulated second");
  app.add_option("--png-every", every, "write every n-th frame as PNG (0: none)");
  app.add_option("--png-level", pngLevel, "zlib level 0..9");
  app.add_option("--from", from, "start time, s");
  app.add_option("--to", to, "end time, s (default: end of the run)");
  app.add_option("--camera", camera)->check(CLI::IsMember({"chase", "hood", "orbit", "top-down"}));
  app.add_option("--body", body)->check(CLI::IsMember({"solid", "translucent", "hidden"}));
  CLI11_PARSE(app, argc, argv);

  try {
    render::SyntheticDrive drive{scenario::makeIso3888Course(1.9, 0.0, -1.75)};
    render::Scene scene(demoScene(drive.course));
    const char* cams[] = {"chase", "hood", "orbit", "top-down"};
    for (int i = 0; i < 4; ++i)
      if (camera == cams[i]) scene.setCamera(static_cast<render::CameraMode>(i));
    scene.setBodyDisplay(body == "solid" ? render::BodyDisplay::Solid
                         : body == "translucent" ? render::BodyDisplay::Translucent
                                                 : render::BodyDisplay::Hidden);
    render::HeadlessRenderer renderer(scene, width, height);
    std::printf("GL_RENDERER %s, GL_VERSION %s\n", renderer.glRenderer().c_str(), renderer.glVersion().c_str());
    if (!outDir.empty() && every > 0) std::filesystem::create_directories(outDir);
    render::PngQueue pngs(pngLevel);
    std::optional<render::VideoPipe> pipe;
    if (!video.empty()) pipe.emplace(video, width, height, render::VideoOptions{fps});

    const double end = to > 0 ? to : render::syntheticDuration(drive);
    int n = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (double t = from; t <= end; t += 1.0 / fps, ++n) {
      const render::SyntheticFrame f = render::syntheticLaneChange(drive, t);
      scene.update(f.view, f.hud);
      const render::Frame& frame = renderer.render();
      if (pipe) pipe->write(frame);
      if (!outDir.empty() && every > 0 && n % every == 0) {
        char name[64];
        std::snprintf(name, sizeof name, "/frame_%05d.png", n);
        pngs.push(outDir + name, frame);
      }
    }
    pngs.flush();
    if (pipe) pipe->close();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%d frames in %.2f s (%.1f ms per frame incl. output), %d PNG files\n", n, s, 1e3 * s / n,
                pngs.written());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bdfcar-render-demo: %s\n", e.what());
    return 1;
  }
  return 0;
}
