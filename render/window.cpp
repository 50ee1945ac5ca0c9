#include "render/window.h"

#include <GL/gl.h>
#include <SDL.h>

#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>

#include "render/embedded_viewer.h"
#include "render/gl_check.h"
#include "render/library_versions.h"
#include "render/png_writer.h"
#include "render/resolution_governor.h"
#include "render/scaled_world.h"

namespace bdfcar::render {

struct Window::Impl {
  explicit Impl(Scene::Impl& s) : scene(s) {}
  Scene::Impl& scene;
  SDL_Window* window = nullptr;
  SDL_GLContext context = nullptr;
  osg::ref_ptr<osgViewer::Viewer> viewer;
  std::unique_ptr<ScaledWorld> scaled;
  std::optional<ResolutionGovernor> governor;  // with renderScale 0
  double fixedScale = 1;
  std::string renderer, screenshotPath;
  int width = 0, height = 0, samples = 0;
};

namespace {

// Mesa's software rasterisers, by the names GL_RENDERER gives them.
bool isSoftwareRenderer(const std::string& renderer) {
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
    if (renderer.find(name) != std::string::npos) return true;
  return false;
}

// Sets the GL attributes SDL uses for the next window's context.
void requestContext(int samples) {
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_COMPATIBILITY);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
  SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 8);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLEBUFFERS, samples > 1 ? 1 : 0);
  SDL_GL_SetAttribute(SDL_GL_MULTISAMPLESAMPLES, samples > 1 ? samples : 0);
}

// RGBA picture of the back buffer, top row first.
Frame readBackBuffer(int width, int height) {
  Frame f = makeFrame(width, height);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, f.rgba.data());
  flipRows(f);
  return f;
}

}  // namespace

// Window, context (MSAA if available, else none), vsync, viewer.
Window::Window(Scene& scene, const WindowOptions& options) : impl_(std::make_unique<Impl>(scene.impl())) {
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0)
    throw RenderError(std::string("SDL2: cannot initialise video: ") + SDL_GetError());
  // With no display server SDL falls back to a driver that draws where nobody
  // sees it: a drive would run on, unseen. Unless that driver was asked for
  // (SDL_VIDEODRIVER, as the window tests do), say so instead.
  const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
  if ((driver == "offscreen" || driver == "dummy") && !std::getenv("SDL_VIDEODRIVER")) {
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw RenderError("no display: neither DISPLAY nor WAYLAND_DISPLAY reaches a display server (SDL2 fell back to "
                      "its '" + driver + "' driver, where nobody would see the window); `bdfcar demo` and `bdfcar "
                      "render` draw frames without a display, SDL_VIDEODRIVER=offscreen runs the window anyway");
  }
  Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
  if (options.fullscreen) flags |= SDL_WINDOW_FULLSCREEN_DESKTOP;
  const bool autoSamples = options.multisample < 0;
  for (int samples : {autoSamples ? 4 : options.multisample, 0}) {
    requestContext(samples);
    impl_->window = SDL_CreateWindow(options.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                     options.width, options.height, flags);
    if (impl_->window) impl_->context = SDL_GL_CreateContext(impl_->window);
    // Multisampling chosen for us on a software rasteriser: the window again without.
    if (impl_->context && autoSamples && samples > 0) {
      SDL_GL_MakeCurrent(impl_->window, impl_->context);
      const auto* r = glGetString(GL_RENDERER);
      if (r && isSoftwareRenderer(reinterpret_cast<const char*>(r))) {
        SDL_GL_MakeCurrent(impl_->window, nullptr);
        SDL_GL_DeleteContext(impl_->context);
        impl_->context = nullptr;
      }
    }
    if (impl_->context) break;
    if (impl_->window) SDL_DestroyWindow(impl_->window);
    impl_->window = nullptr;
    if (samples == 0) break;
  }
  if (!impl_->context) {
    const std::string error = SDL_GetError();
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw RenderError("SDL2: cannot create an OpenGL compatibility window: " + error);
  }
  SDL_GL_MakeCurrent(impl_->window, impl_->context);
  SDL_GL_SetSwapInterval(options.vsync ? 1 : 0);
  try {
    const auto* r = glGetString(GL_RENDERER);
    requireGlContext(r, "SDL2 window");
    impl_->renderer = reinterpret_cast<const char*>(r);
    if (SDL_GL_GetAttribute(SDL_GL_MULTISAMPLESAMPLES, &impl_->samples) != 0) impl_->samples = 0;
    SDL_GL_GetDrawableSize(impl_->window, &impl_->width, &impl_->height);
    impl_->viewer = makeEmbeddedViewer(impl_->scene, impl_->width, impl_->height);
    Scene::Impl& s = impl_->scene;
    impl_->scaled = std::make_unique<ScaledWorld>(s.sky.get(), s.world.get(), s.config.hud ? s.hud.node() : nullptr);
    impl_->viewer->setSceneData(impl_->scaled->root());
    // Automatic: on a GPU the world's resolution follows the frame rate. Not on
    // software GL, where stretching the picture over the window costs as much
    // as the pixels saved (llvmpipe, 1280x720: the stretch 27 M instructions a
    // frame, the whole world's shading at full size 34 M; docs/RESULTS.md 8).
    if (options.renderScale > 0)
      impl_->fixedScale = options.renderScale;
    else if (!isSoftwareRenderer(impl_->renderer))
      impl_->governor.emplace();
  } catch (...) {
    SDL_GL_DeleteContext(impl_->context);
    SDL_DestroyWindow(impl_->window);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw;
  }
}

Window::~Window() {
  SDL_GL_MakeCurrent(impl_->window, impl_->context);
  releaseViewer(*impl_->viewer);
  impl_->viewer = nullptr;
  SDL_GL_DeleteContext(impl_->context);
  SDL_DestroyWindow(impl_->window);
  SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

// Draws at the current drawable size (the window may have been resized), reads back if asked, swaps.
void Window::releaseContext() { SDL_GL_MakeCurrent(impl_->window, nullptr); }

WindowEvents Window::takeEvents() {
  WindowEvents w;
  SDL_Event e[32];
  int n;
  while ((n = SDL_PeepEvents(e, 32, SDL_GETEVENT, SDL_QUIT, SDL_QUIT)) > 0) w.quit = true;
  while ((n = SDL_PeepEvents(e, 32, SDL_GETEVENT, SDL_WINDOWEVENT, SDL_SYSWMEVENT)) > 0)
    for (int i = 0; i < n; ++i)
      if (e[i].type == SDL_WINDOWEVENT && e[i].window.event == SDL_WINDOWEVENT_CLOSE) w.quit = true;
  while ((n = SDL_PeepEvents(e, 32, SDL_GETEVENT, SDL_MOUSEMOTION, SDL_MOUSEWHEEL)) > 0)
    for (int i = 0; i < n; ++i) {
      if (e[i].type == SDL_MOUSEMOTION && (e[i].motion.state & SDL_BUTTON_LMASK)) {
        w.dragX += e[i].motion.xrel;
        w.dragY += e[i].motion.yrel;
      }
      if (e[i].type == SDL_MOUSEWHEEL) w.wheel += e[i].wheel.y;
    }
  return w;
}

void Window::present(Frame* capture) {
  SDL_GL_MakeCurrent(impl_->window, impl_->context);
  SDL_GL_GetDrawableSize(impl_->window, &impl_->width, &impl_->height);
  const auto t0 = std::chrono::steady_clock::now();
  impl_->scaled->set(impl_->governor ? impl_->governor->scale() : impl_->fixedScale, impl_->width, impl_->height);
  drawFrame(*impl_->viewer, impl_->scene, impl_->width, impl_->height);
  if (capture || !impl_->screenshotPath.empty()) {
    Frame f = readBackBuffer(impl_->width, impl_->height);
    requireNotBlack(f, "SDL2 window");
    if (!impl_->screenshotPath.empty()) {
      writePng(impl_->screenshotPath, f);
      impl_->screenshotPath.clear();
    }
    if (capture) *capture = std::move(f);
  }
  SDL_GL_SwapWindow(impl_->window);
  if (impl_->governor)
    impl_->governor->frame(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

void Window::screenshotNextFrame(const std::string& pngPath) { impl_->screenshotPath = pngPath; }
int Window::width() const { return impl_->width; }
int Window::height() const { return impl_->height; }
const std::string& Window::glRenderer() const { return impl_->renderer; }
double Window::worldScale() const { return impl_->scaled->scale(); }
int Window::samples() const { return impl_->samples; }
void Window::setTitle(const std::string& title) { SDL_SetWindowTitle(impl_->window, title.c_str()); }

std::string sdlVersion() {
  SDL_version compiled, linked;
  SDL_VERSION(&compiled);
  SDL_GetVersion(&linked);
  auto text = [](const SDL_version& v) {
    return std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.patch);
  };
  return "SDL2 " + text(linked) + " (compiled against " + text(compiled) + ")";
}

}  // namespace bdfcar::render
