// The public bdfcar::Camera (include/bdfcar/camera.h) over api::CameraCore.
#include "bdfcar/camera.h"

#include "camera_core.h"

namespace bdfcar {

Camera::Camera(Car& car, int width, int height, const std::string& camera, bool hud)
    : core_(std::make_unique<api::CameraCore>(car.core(), width, height, camera, hud)) {}
Camera::~Camera() = default;

std::vector<std::uint8_t> Camera::render() {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(core_->width()) * core_->height() * 3);
  core_->render(rgb.data());
  return rgb;
}

int Camera::width() const { return core_->width(); }
int Camera::height() const { return core_->height(); }
std::string Camera::renderer() const { return core_->renderer(); }

}  // namespace bdfcar
