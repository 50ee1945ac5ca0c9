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

#include "camera_core.h"

namespace py = pybind11;
using namespace bdfcar;

namespace {

// (height, width, 3) RGB, row 0 at the top.
py::array_t<std::uint8_t> renderFrame(api::CameraCore& c) {
  py::array_t<std::uint8_t> out({c.height(), c.width(), 3});
  c.render(out.mutable_data());
  return out;
}

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
  py::class_<api::CameraCore>(m, "Camera", "Draws a car's world headless (OSMesa): frames as NumPy arrays")
      .def(py::init<api::CarCore&, int, int, const std::string&, bool>(), py::arg("car"), py::arg("width") = 640,
           py::arg("height") = 360, py::arg("camera") = "chase", py::arg("hud") = false, py::keep_alive<1, 2>(),
           "A camera on the car (chase, hood, orbit or top-down), frames of width x height pixels")
      .def("render", &renderFrame, "The car as it is now: (height, width, 3) uint8 RGB, row 0 at the top")
      .def_property_readonly("renderer", &api::CameraCore::renderer, "GL_RENDERER (e.g. llvmpipe)")
      .def_property_readonly("warnings", &api::CameraCore::warnings, "What the scene could not draw as asked");
}
