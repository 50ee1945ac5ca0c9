#include "camera_core.h"

#include <stdexcept>

#include "view/scene_setup.h"

namespace bdfcar::api {

namespace {

render::CameraMode cameraMode(const std::string& name) {
  if (name == "chase") return render::CameraMode::Chase;
  if (name == "hood") return render::CameraMode::Hood;
  if (name == "orbit") return render::CameraMode::Orbit;
  if (name == "top-down") return render::CameraMode::TopDown;
  throw std::invalid_argument("camera: expected chase, hood, orbit or top-down, got \"" + name + "\"");
}

}  // namespace

CameraCore::CameraCore(CarCore& car, int width, int height, const std::string& camera, bool hud)
    : car_(car), hud_(hud), width_(width), height_(height) {
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throw std::invalid_argument("frame size: expected 16 to 8192 pixels a side, got " + std::to_string(width) + "x" +
                                std::to_string(height));
  const render::CameraMode mode = cameraMode(camera);
  scene_ = std::make_unique<render::Scene>(app::sceneConfigFor(car.simulation(), hud));
  scene_->setCamera(mode);
  renderer_ = std::make_unique<render::HeadlessRenderer>(*scene_, width, height);
}

CameraCore::~CameraCore() = default;

void CameraCore::render(std::uint8_t* rgb) {
  scene_->update(car_.view(), hud_ ? car_.hud() : vehicle::HudInfo{});
  const render::Frame& f = renderer_->render();
  const std::size_t pixels = static_cast<std::size_t>(f.width) * f.height;
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = f.rgba[4 * i + c];
}

}  // namespace bdfcar::api
