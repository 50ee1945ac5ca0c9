// A car's frames drawn headless (OSMesa, render/headless.h) into memory:
// the scene `bdfcar render` draws, with the car as it is now. Behind the
// public bdfcar::Camera (include/bdfcar/camera.h) and Python's
// bdfcar.Camera. A process that draws this way must have libOSMesa ahead of
// any other libGL (render/README.md).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "car_core.h"
#include "render/headless.h"

namespace bdfcar::api {

class CameraCore {
 public:
  // camera: chase, hood, orbit or top-down; throws std::invalid_argument
  // for another name or a side outside [16, 8192] pixels, render::RenderError
  // when no OSMesa context can be made.
  CameraCore(CarCore& car, int width, int height, const std::string& camera, bool hud);
  ~CameraCore();
  // The car now: height x width RGB bytes, row 0 at the top.
  void render(std::uint8_t* rgb);
  int width() const { return width_; }
  int height() const { return height_; }
  const std::string& renderer() const { return renderer_->glRenderer(); }
  const std::vector<std::string>& warnings() const { return scene_->warnings(); }

 private:
  CarCore& car_;
  bool hud_;
  int width_, height_;
  std::unique_ptr<render::Scene> scene_;
  std::unique_ptr<render::HeadlessRenderer> renderer_;
};

}  // namespace bdfcar::api
