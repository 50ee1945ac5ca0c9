// Headless rendering with OSMesa (Mesa's software rasteriser into a memory
// buffer): no display server, no X, no Xvfb. An executable using this must link
// bdfcar_render_headless, which puts libOSMesa first in its NEEDED list, and
// must NOT also link bdfcar_render_window (GLX and OSMesa in one process break).
#pragma once

#include <memory>
#include <string>

#include "render/frame.h"
#include "render/scene.h"

namespace bdfcar::render {

class HeadlessRenderer {
 public:
  // Creates the OSMesa context and the viewer; throws RenderError naming libOSMesa
  // if the context cannot be created or GL_RENDERER is null.
  HeadlessRenderer(Scene& scene, int width, int height);
  ~HeadlessRenderer();
  HeadlessRenderer(const HeadlessRenderer&) = delete;
  HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

  // Draws the scene's current state (call Scene::update first); the frame stays
  // valid until the next render() or resize(). Throws RenderError on an all-black frame.
  const Frame& render();
  void resize(int width, int height);
  // What the last render() drew.
  DrawLoad lastLoad() const;

  int width() const;
  int height() const;
  const std::string& glRenderer() const;  // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  const std::string& glVersion() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bdfcar::render
