// Drawing on a thread of its own at display rate, from the latest state the
// tick handler published; view commands (camera, body display, orbit drag
// and zoom) are handed over with it. The thread runs at a lower priority: on
// a machine without a GPU a frame takes longer than a tick, and the tick must
// not wait for it.
#pragma once

#include <atomic>
#include <mutex>
#include <string>
#include <thread>

#include "render/scene.h"
#include "render/window.h"
#include "session/loop_stats.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::app {

struct ViewCommands {
  int cameraSwitches = 0, bodySwitches = 0;
  double orbitYaw = 0, orbitPitch = 0, zoom = 1;
};

class DrawThread {
 public:
  // Starts drawing `first` at once; `screenshot` (if set) is the last frame's PNG.
  DrawThread(render::Scene& scene, render::Window& window, LoopStats& stats, std::mutex& statsMutex,
             const vehicle::VehicleView& firstView, const vehicle::HudInfo& firstHud, const std::string& screenshot);
  ~DrawThread();  // stops and joins
  void publish(vehicle::VehicleView view, vehicle::HudInfo hud);
  void command(const ViewCommands& c);
  void stop();

 private:
  void loop();

  render::Scene& scene_;
  render::Window& window_;
  LoopStats& stats_;
  std::mutex& statsMutex_;
  std::mutex mutex_;
  vehicle::VehicleView view_;
  vehicle::HudInfo hud_;
  ViewCommands pending_;
  std::string screenshot_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace bdfcar::app
