#include "interactive/drive_loop.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "input/input_system.h"
#include "render/window.h"
#include "view/scene_setup.h"

namespace bdfcar::app {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kTick = 0.01;       // s: the driver-input and physics period
constexpr int kMaxCatchUp = 5;       // ticks run back to back at most before the clock is reset

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// Sleeps until the deadline: coarse sleep, then a short spin (STACK-NOTES:
// median 10.000 ms, p99 13-15 ms with sleep alone on this shared VM).
// recording-1.txt, recording-2.txt, ... in the working folder, the first free name.
std::string nextRecordingName() {
  for (int i = 1;; ++i) {
    const std::string name = "recording-" + std::to_string(i) + ".txt";
    if (!std::filesystem::exists(name)) return name;
  }
}

void waitUntil(Clock::time_point deadline) {
  const auto spin = std::chrono::microseconds(800);
  const auto now = Clock::now();
  if (deadline - now > spin) std::this_thread::sleep_for(deadline - now - spin);
  while (Clock::now() < deadline) {
  }
}

// What the physics thread hands the render thread, and the view commands back.
struct Shared {
  std::mutex mutex;
  vehicle::VehicleView view;
  vehicle::HudInfo hud;
  long version = 0;
  int cameraSwitches = 0, bodySwitches = 0;
  double orbitYaw = 0, orbitPitch = 0, zoom = 1;
  std::atomic<bool> running{true};
  std::string screenshot;
};

}  // namespace

LoopStats runInteractive(DriveSession& session, const InteractiveOptions& opt) {
  // With software GL (Mesa llvmpipe, no GPU) drawing threads share the cores
  // with the 10 ms tick: one drawing thread keeps the tick on time (p99 of
  // the tick period 11.4 ms against 13.8 ms with two, on two cores). Real GPU
  // drivers ignore the variable; a value the user set wins.
  setenv("LP_NUM_THREADS", "1", 0);
  LoopStats stats;
  render::Scene scene(sceneConfigFor(session));
  for (const std::string& w : scene.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  render::WindowOptions wo;
  wo.width = opt.width;
  wo.height = opt.height;
  wo.vsync = opt.vsync;
  wo.title = "bdfcar - " + session.spec().name;
  render::Window window(scene, wo);
  std::unique_ptr<input::InputSystem> devices;
  if (opt.driver == DriverSource::Person) {
    input::InputOptions io;
    io.onMessage = [](const std::string& m) { std::fprintf(stderr, "input: %s\n", m.c_str()); };
    devices = std::make_unique<input::InputSystem>(io);
  }

  Shared shared;
  shared.view = session.view();
  shared.hud = session.hud(0, 0, "");
  shared.screenshot = opt.screenshot;
  window.releaseContext();
  std::mutex statsMutex;

  // Render thread: draws the latest state at display rate.
  std::thread renderer([&] {
    // Drawing yields to the physics tick: on a machine without a GPU a frame
    // takes longer than a tick, and the tick must not wait for it.
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
    long drawn = -1;
    while (shared.running) {
      vehicle::VehicleView view;
      vehicle::HudInfo hud;
      int cam = 0, body = 0;
      double oy = 0, op = 0, zoom = 1;
      {
        std::lock_guard<std::mutex> lock(shared.mutex);
        view = shared.view;
        hud = shared.hud;
        std::swap(cam, shared.cameraSwitches);
        std::swap(body, shared.bodySwitches);
        std::swap(oy, shared.orbitYaw);
        std::swap(op, shared.orbitPitch);
        std::swap(zoom, shared.zoom);
        drawn = shared.version;
      }
      for (int i = 0; i < cam; ++i) scene.nextCamera();
      for (int i = 0; i < body; ++i) scene.nextBodyDisplay();
      if (oy != 0 || op != 0 || zoom != 1) scene.orbitBy(oy, op, zoom);
      const auto t0 = Clock::now();
      scene.update(view, hud);
      window.present();
      std::lock_guard<std::mutex> lock(statsMutex);
      stats.frame(seconds(Clock::now() - t0));
    }
    (void)drawn;
    if (!shared.screenshot.empty()) {
      window.screenshotNextFrame(shared.screenshot);
      window.present();
    }
    window.releaseContext();
  });

  // Physics and input on this thread.
  bool paused = false;
  long replayTick = 0;
  const auto start = Clock::now();
  auto deadline = start;
  auto lastTick = start;
  double stepSeconds = 0;
  std::string message;
  while (true) {
    deadline += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kTick));
    waitUntil(deadline);
    const auto t0 = Clock::now();
    const double period = seconds(t0 - lastTick);
    lastTick = t0;
    const render::WindowEvents we = window.takeEvents();
    bool quit = we.quit, step = false, restart = false;
    std::optional<scenario::DriverInput> in;
    if (devices) {
      const input::Controls c = devices->poll(kTick);
      quit |= c.quit;
      if (c.pause) paused = !paused;
      step = c.singleStep;
      restart = c.reset;
      if (c.record) {
        // A recording replays only from the scenario's start: restart into a new file.
        session.startRecording(nextRecordingName());
        message = "recording to " + session.recordingPath();
        restart = false;
        replayTick = 0;
      }
      std::lock_guard<std::mutex> lock(shared.mutex);
      shared.cameraSwitches += c.camera ? 1 : 0;
      shared.bodySwitches += c.view ? 1 : 0;
      in = scenario::DriverInput{c.steering, c.throttle, c.brake};
    } else if (opt.driver == DriverSource::Replay && opt.replay) {
      if (replayTick < static_cast<long>(opt.replay->inputs.size())) in = opt.replay->inputs[replayTick];
    }
    {
      std::lock_guard<std::mutex> lock(shared.mutex);
      shared.orbitYaw -= 0.005 * we.dragX;
      shared.orbitPitch += 0.005 * we.dragY;
      shared.zoom *= std::pow(0.9, we.wheel);
    }
    if (quit) break;
    if (opt.seconds > 0 && seconds(t0 - start) >= opt.seconds) break;
    if (restart) {
      session.restart();
      replayTick = 0;
    }
    if ((!paused || step) && !session.failed() && !session.finished()) {
      if (opt.driver == DriverSource::Replay && !in) {
        message = "replay finished";
      } else {
        session.tick(opt.driver == DriverSource::Scripted ? std::nullopt : in);
        ++replayTick;
      }
    }
    stepSeconds = seconds(Clock::now() - t0);
    if (session.finished()) {
      message = "scenario finished";
      if (opt.quitAtEnd) break;
    }
    if (devices) devices->setSteeringTorque(session.steeringFeel());
    const double rtf = period > 0 ? kTick / period : 0;
    {
      vehicle::VehicleView view = session.view();
      vehicle::HudInfo hud = session.hud(rtf, stepSeconds, paused ? "paused" : message);
      std::lock_guard<std::mutex> lock(shared.mutex);
      shared.view = std::move(view);
      shared.hud = std::move(hud);
      ++shared.version;
    }
    // Capped catch-up: far behind (a stall), restart the clock instead of racing.
    const bool overrun = Clock::now() - deadline > std::chrono::duration<double>(kTick);
    {
      std::lock_guard<std::mutex> lock(statsMutex);
      stats.tick(period, stepSeconds, overrun);
    }
    if (Clock::now() - deadline > std::chrono::duration<double>(kMaxCatchUp * kTick)) deadline = Clock::now();
  }
  shared.running = false;
  renderer.join();
  return stats;
}

}  // namespace bdfcar::app
