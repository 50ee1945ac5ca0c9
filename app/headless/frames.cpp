#include "headless/frames.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "audio/car_synth.h"
#include "audio/wav_file.h"
#include "render/headless.h"
#include "render/png_queue.h"
#include "render/video_pipe.h"
#include "demo_common.h"
#include "interrupt.h"
#include "session/car_sound.h"
#include "view/scene_setup.h"

namespace bdfcar::app {

namespace {
using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

render::CameraMode cameraMode(const std::string& name) {
  if (name == "hood") return render::CameraMode::Hood;
  if (name == "orbit") return render::CameraMode::Orbit;
  if (name == "top-down") return render::CameraMode::TopDown;
  return render::CameraMode::Chase;
}
}  // namespace

FramesResult renderFrames(DriveSession& session, const FramesOptions& opt) {
  FramesResult r;
  r.width = opt.width;
  r.height = opt.height;
  render::Scene scene(sceneConfigFor(session));
  for (const std::string& w : scene.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  scene.setCamera(cameraMode(opt.camera));
  scene.setBodyDisplay(opt.body == "hidden"        ? render::BodyDisplay::Hidden
                       : opt.body == "translucent" ? render::BodyDisplay::Translucent
                                                   : render::BodyDisplay::Solid);
  render::HeadlessRenderer renderer(scene, opt.width, opt.height);
  r.renderer = renderer.glRenderer();
  if (!opt.outDir.empty()) std::filesystem::create_directories(opt.outDir);
  std::unique_ptr<render::PngQueue> pngs;
  if (!opt.outDir.empty()) pngs = std::make_unique<render::PngQueue>();
  std::unique_ptr<render::VideoPipe> video;
  if (!opt.video.empty()) {
    render::VideoOptions vo;
    vo.fps = opt.fps;  // played at the rate it was rendered at: its duration is the manoeuvre's
    video = std::make_unique<render::VideoPipe>(opt.video, opt.width, opt.height, vo);
  }

  // The soundtrack: a tick's worth of samples after each tick.
  constexpr int kSoundRate = 48000;
  std::unique_ptr<audio::WavFile> wav;
  std::unique_ptr<audio::CarSynth> synth;
  CarSound carSound;
  std::vector<float> samples(static_cast<size_t>(std::lround(session.spec().tick * kSoundRate)));
  if (!opt.wav.empty()) {
    wav = std::make_unique<audio::WavFile>(opt.wav, kSoundRate);
    synth = std::make_unique<audio::CarSynth>(kSoundRate);
  }

  std::vector<double> drawables, triangles;  // per frame
  const double frameDt = 1.0 / opt.fps;
  const auto wall0 = Clock::now();
  const double sim0 = session.time();
  double lastStep = 0;
  double nextFrame = 0.0;  // manoeuvre time of the next frame
  const double h = session.spec().tick;  // frames fall on driver ticks
  while (true) {
    if (session.time() >= nextFrame - 0.5 * h) {
      const auto t0 = Clock::now();
      const vehicle::VehicleView view = session.view();
      const double wall = seconds(t0 - wall0);
      // Once the course is decided its verdict is the closing card (the message line).
      const auto course = session.courseResult();
      const bool decided = course && (course->exitTime >= 0 || !course->passed);
      vehicle::HudInfo hud = session.hud(wall > 0 ? (session.time() - sim0) / wall : 0.0, lastStep,
                                         decided ? courseVerdictLine(session) : "");
      hud.realTimeLabel = "render";  // simulated time per wall second, drawing and encoding included
      scene.update(view, hud);
      const render::Frame& f = renderer.render();
      r.stats.frame(seconds(Clock::now() - t0));
      const render::DrawLoad load = renderer.lastLoad();
      drawables.push_back(load.drawables);
      triangles.push_back(load.triangles);
      const auto t1 = Clock::now();
      if (pngs) {
        char name[64];
        std::snprintf(name, sizeof name, "frame_%05d.png", r.frames);
        pngs->push((std::filesystem::path(opt.outDir) / name).string(), f);
      }
      if (video) video->write(f);
      r.encodeSeconds += seconds(Clock::now() - t1);
      ++r.frames;
      nextFrame += frameDt;
    }
    if (session.finished() || session.failed() || interruptRequested()) break;
    const auto t0 = Clock::now();
    session.tick(std::nullopt);
    lastStep = seconds(Clock::now() - t0);
    r.stats.tick(0, lastStep, false);
    if (wav) {
      synth->render(carSound.update(session), samples.data(), static_cast<int>(samples.size()));
      wav->write(samples.data(), static_cast<long>(samples.size()));
    }
  }
  const auto t1 = Clock::now();
  if (pngs) {
    pngs->flush();
    r.pngEncode = percentiles(pngs->encodeSeconds());
  }
  if (video) video->close();
  if (wav) {
    wav->close();
    r.soundFrames = wav->frames();
  }
  r.encodeSeconds += seconds(Clock::now() - t1);
  r.wallSeconds = seconds(Clock::now() - wall0);
  r.drawnP50 = {static_cast<unsigned>(percentiles(drawables).p50),
                static_cast<unsigned long>(percentiles(triangles).p50)};
  return r;
}

}  // namespace bdfcar::app
