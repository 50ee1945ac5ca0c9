// bench_render: headless (OSMesa) frame time of the synthetic lane change at
// 1280x720, render and PNG encode measured separately; medians over N frames.
// Not a test (no assertion on time): run it and read the numbers.
//   bench_render [frames=100] [width=1280] [height=720] [pngLevel=1, -1: no PNG]
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

#include "render/headless.h"
#include "render/png_writer.h"
#include "render/synthetic_drive.h"

using namespace bdfcar;
using Clock = std::chrono::steady_clock;

// Median and 90th percentile of a sample, ms.
static void report(const char* what, std::vector<double> ms) {
  std::sort(ms.begin(), ms.end());
  const auto at = [&](double q) { return ms[std::min(ms.size() - 1, static_cast<std::size_t>(q * ms.size()))]; };
  std::printf("%-22s median %7.2f ms   p90 %7.2f ms   min %7.2f ms   (n = %zu)\n", what, at(0.5), at(0.9), ms.front(),
              ms.size());
}

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : 100;
  const int width = argc > 2 ? std::atoi(argv[2]) : 1280, height = argc > 3 ? std::atoi(argv[3]) : 720;
  const int level = argc > 4 ? std::atoi(argv[4]) : 1;
  try {
    render::SyntheticDrive drive{scenario::makeIso3888Course(1.9, 0.0, -1.75)};
    render::SceneConfig cfg;
    cfg.terrain.road.present = true;
    cfg.course = drive.course;
    cfg.geometry.bodyMesh = "assets/models/sedan_body.obj";
    render::Scene scene(cfg);
    render::HeadlessRenderer renderer(scene, width, height);
    std::printf("%s | %dx%d | %d frames | PNG zlib level %d\n", renderer.glRenderer().c_str(), width, height, frames,
                level);
    const std::string png = (std::filesystem::temp_directory_path() / "bench_render.png").string();
    std::vector<double> renderMs, pngMs;
    const double dt = render::syntheticDuration(drive) / std::max(frames, 1);
    for (int i = -5; i < frames; ++i) {  // 5 warm-up frames: llvmpipe compiles its shaders on first use
      const render::SyntheticFrame f = render::syntheticLaneChange(drive, std::max(i, 0) * dt);
      const auto t0 = Clock::now();
      scene.update(f.view, f.hud);
      const render::Frame& frame = renderer.render();
      const auto t1 = Clock::now();
      if (level >= 0) render::writePng(png, frame, level);
      const auto t2 = Clock::now();
      if (i == -1) CALLGRIND_START_INSTRUMENTATION;  // under callgrind --instr-atstart=no: the measured frames only
      if (i < 0) continue;
      renderMs.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      pngMs.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    }
    CALLGRIND_STOP_INSTRUMENTATION;
    report("render (update+draw)", renderMs);
    if (level >= 0) {
      report("PNG encode + write", pngMs);
      std::printf("last PNG %ju bytes\n", static_cast<std::uintmax_t>(std::filesystem::file_size(png)));
      std::filesystem::remove(png);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_render: %s\n", e.what());
    return 1;
  }
  return 0;
}
