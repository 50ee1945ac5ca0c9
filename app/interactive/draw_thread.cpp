#include "interactive/draw_thread.h"

#include <chrono>

#include "render/thread_priority.h"

namespace bdfcar::app {

DrawThread::DrawThread(render::Scene& scene, render::Window& window, LoopStats& stats, std::mutex& statsMutex,
                       const vehicle::VehicleView& firstView, const vehicle::HudInfo& firstHud,
                       const std::string& screenshot)
    : scene_(scene),
      window_(window),
      stats_(stats),
      statsMutex_(statsMutex),
      view_(firstView),
      hud_(firstHud),
      screenshot_(screenshot) {
  window_.releaseContext();
  thread_ = std::thread([this] { loop(); });
}

DrawThread::~DrawThread() { stop(); }

void DrawThread::stop() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

void DrawThread::publish(vehicle::VehicleView view, vehicle::HudInfo hud) {
  std::lock_guard<std::mutex> lock(mutex_);
  view_ = std::move(view);
  hud_ = std::move(hud);
}

void DrawThread::command(const ViewCommands& c) {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_.cameraSwitches += c.cameraSwitches;
  pending_.bodySwitches += c.bodySwitches;
  pending_.orbitYaw += c.orbitYaw;
  pending_.orbitPitch += c.orbitPitch;
  pending_.zoom *= c.zoom;
}

void DrawThread::loop() {
  // The tick first: drawing may lag, it draws the latest state (render/thread_priority.h).
  render::lowerThisThreadsPriority();
  render::lowerSoftwareRasteriserPriority();
  while (running_) {
    vehicle::VehicleView view;
    vehicle::HudInfo hud;
    ViewCommands c;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      view = view_;
      hud = hud_;
      std::swap(c, pending_);
    }
    for (int i = 0; i < c.cameraSwitches; ++i) scene_.nextCamera();
    for (int i = 0; i < c.bodySwitches; ++i) scene_.nextBodyDisplay();
    if (c.orbitYaw != 0 || c.orbitPitch != 0 || c.zoom != 1) scene_.orbitBy(c.orbitYaw, c.orbitPitch, c.zoom);
    const auto t0 = std::chrono::steady_clock::now();
    scene_.update(view, hud);
    window_.present();
    std::lock_guard<std::mutex> lock(statsMutex_);
    stats_.frame(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), window_.worldScale());
  }
  if (!screenshot_.empty()) {
    window_.screenshotNextFrame(screenshot_);
    window_.present();
  }
  window_.releaseContext();
}

}  // namespace bdfcar::app
