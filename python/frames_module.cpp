// The Python module `bdfcar._frames`: a car's frames as NumPy arrays,
// drawn headless through OSMesa (render/headless.h). A module of its own so
// that `import bdfcar` loads no GL: bdfcar.Camera imports it when first
// used. libOSMesa is this module's first NEEDED library (as in
// bdfcar-headless), so its gl* symbols are the ones OpenSceneGraph finds.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "car.h"
#include "render/headless.h"
#include "view/scene_setup.h"

namespace py = pybind11;
using namespace bdfcar;

namespace {

render::CameraMode cameraMode(const std::string& name) {
  if (name == "chase") return render::CameraMode::Chase;
  if (name == "hood") return render::CameraMode::Hood;
  if (name == "orbit") return render::CameraMode::Orbit;
  if (name == "top-down") return render::CameraMode::TopDown;
  throw py::value_error("camera: expected chase, hood, orbit or top-down, got \"" + name + "\"");
}

// A scene of one car's world and a renderer; draws the car as it is now.
class Camera {
 public:
  Camera(python::Car& car, int width, int height, const std::string& camera, bool hud) : car_(car), hud_(hud) {
    if (width < 16 || height < 16 || width > 8192 || height > 8192)
      throw py::value_error("frame size: expected 16 to 8192 pixels a side, got " + std::to_string(width) + "x" +
                            std::to_string(height));
    const render::CameraMode mode = cameraMode(camera);
    scene_ = std::make_unique<render::Scene>(app::sceneConfigFor(car.simulation(), hud));
    scene_->setCamera(mode);
    renderer_ = std::make_unique<render::HeadlessRenderer>(*scene_, width, height);
  }

  // (height, width, 3) RGB, row 0 at the top.
  py::array_t<std::uint8_t> render() {
    scene_->update(car_.view(), hud_ ? car_.hud() : vehicle::HudInfo{});
    const render::Frame& f = renderer_->render();
    py::array_t<std::uint8_t> out({f.height, f.width, 3});
    std::uint8_t* o = out.mutable_data();
    const std::size_t pixels = static_cast<std::size_t>(f.width) * f.height;
    for (std::size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) o[3 * i + c] = f.rgba[4 * i + c];
    return out;
  }

  const std::string& renderer() const { return renderer_->glRenderer(); }
  const std::vector<std::string>& warnings() const { return scene_->warnings(); }

 private:
  python::Car& car_;
  bool hud_;
  std::unique_ptr<render::Scene> scene_;
  std::unique_ptr<render::HeadlessRenderer> renderer_;
};

}  // namespace

PYBIND11_MODULE(_frames, m) {
  m.doc() = "bdfcar's headless frames (OSMesa) as NumPy arrays";
  py::module_::import("bdfcar._bdfcar");  // the Car type
  static py::exception<render::RenderError> renderError(m, "RenderError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const render::RenderError& e) {
      renderError(e.what());
    }
  });
  py::class_<Camera>(m, "Camera", "Draws a car's world headless (OSMesa): frames as NumPy arrays")
      .def(py::init<python::Car&, int, int, const std::string&, bool>(), py::arg("car"), py::arg("width") = 640,
           py::arg("height") = 360, py::arg("camera") = "chase", py::arg("hud") = false, py::keep_alive<1, 2>(),
           "A camera on the car (chase, hood, orbit or top-down), frames of width x height pixels")
      .def("render", &Camera::render, "The car as it is now: (height, width, 3) uint8 RGB, row 0 at the top")
      .def_property_readonly("renderer", &Camera::renderer, "GL_RENDERER (e.g. llvmpipe)")
      .def_property_readonly("warnings", &Camera::warnings, "What the scene could not draw as asked");
}
