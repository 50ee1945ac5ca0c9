#include "render/headless.h"

#include <GL/osmesa.h>

#include "render/embedded_viewer.h"
#include "render/gl_check.h"

namespace bdfcar::render {

struct HeadlessRenderer::Impl {
  Scene::Impl& scene;
  OSMesaContext context = nullptr;
  Frame frame;  // OSMesa renders straight into frame.rgba
  osg::ref_ptr<osgViewer::Viewer> viewer;
  std::string renderer, version;

  // Binds the context to the frame buffer, rows top first.
  void makeCurrent() {
    if (!OSMesaMakeCurrent(context, frame.rgba.data(), GL_UNSIGNED_BYTE, frame.width, frame.height))
      throw RenderError("OSMesa (libOSMesa): OSMesaMakeCurrent failed for " + std::to_string(frame.width) + "x" +
                        std::to_string(frame.height));
    OSMesaPixelStore(OSMESA_Y_UP, 0);
  }
};

// RGBA context with 24-bit depth and 8-bit stencil, compatibility profile (OSG's fixed-function state needs it).
HeadlessRenderer::HeadlessRenderer(Scene& scene, int width, int height)
    : impl_(std::make_unique<Impl>(Impl{scene.impl(), nullptr, makeFrame(width, height), nullptr, "", ""})) {
  impl_->context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!impl_->context)
    throw RenderError("OSMesa: OSMesaCreateContextExt failed; headless rendering needs libOSMesa "
                      "(Debian package libosmesa6) with its llvmpipe/softpipe driver");
  try {
    impl_->makeCurrent();
    const auto* r = glGetString(GL_RENDERER);
    requireGlContext(r, "OSMesa headless renderer");
    impl_->renderer = reinterpret_cast<const char*>(r);
    const auto* v = glGetString(GL_VERSION);
    impl_->version = v ? reinterpret_cast<const char*>(v) : "";
    impl_->viewer = makeEmbeddedViewer(impl_->scene, width, height);
  } catch (...) {
    OSMesaDestroyContext(impl_->context);
    throw;
  }
}

HeadlessRenderer::~HeadlessRenderer() {
  if (impl_->viewer) {
    try {
      impl_->makeCurrent();
    } catch (...) {
      // Destroying anyway: nothing better to do in a destructor.
    }
    releaseViewer(*impl_->viewer);
    impl_->viewer = nullptr;
  }
  OSMesaDestroyContext(impl_->context);
}

// Renders into the frame buffer and waits for the rasteriser to finish.
const Frame& HeadlessRenderer::render() {
  impl_->makeCurrent();
  drawFrame(*impl_->viewer, impl_->scene, impl_->frame.width, impl_->frame.height);
  glFinish();
  requireNotBlack(impl_->frame, "OSMesa headless renderer");
  return impl_->frame;
}

// New buffer size; the viewer follows on the next render().
void HeadlessRenderer::resize(int width, int height) {
  impl_->frame = makeFrame(width, height);
  impl_->makeCurrent();
}

DrawLoad HeadlessRenderer::lastLoad() const { return lastDrawLoad(*impl_->viewer); }

int HeadlessRenderer::width() const { return impl_->frame.width; }
int HeadlessRenderer::height() const { return impl_->frame.height; }
const std::string& HeadlessRenderer::glRenderer() const { return impl_->renderer; }
const std::string& HeadlessRenderer::glVersion() const { return impl_->version; }

}  // namespace bdfcar::render
