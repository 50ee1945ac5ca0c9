// A car's frames drawn headless (OSMesa: no display needed) into memory.
// Library bdfcar::frames (shared): a program linking it has libOSMesa ahead
// of any other libGL, which the package's target arranges.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bdfcar/bdfcar.h"

namespace bdfcar {

namespace api {
class CameraCore;
}

class Camera {
 public:
  // camera: chase, hood, orbit or top-down.
  Camera(Car& car, int width, int height, const std::string& camera = "chase", bool hud = false);
  ~Camera();
  // The car now: height x width x 3 RGB bytes, row 0 at the top.
  std::vector<std::uint8_t> render();
  int width() const;
  int height() const;
  std::string renderer() const;  // GL_RENDERER

 private:
  std::unique_ptr<api::CameraCore> core_;
};

}  // namespace bdfcar
