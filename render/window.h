// On-screen rendering: an SDL2 window with an OpenGL compatibility context and
// the scene drawn by an embedded OSG viewer. The window never polls SDL events
// (input/ owns the event queue); it follows the drawable size every frame.
// Do not link this together with bdfcar_render_headless into one executable.
#pragma once

#include <memory>
#include <string>

#include "render/frame.h"
#include "render/scene.h"

namespace bdfcar::render {

// What the window's own events asked for since the last call (close button,
// mouse drags for the orbit camera). Keyboard and devices belong to input/.
struct WindowEvents {
  bool quit = false;
  double dragX = 0, dragY = 0;  // pixels moved with the left button held
  double wheel = 0;             // wheel clicks (+ = away from the user)
};

struct WindowOptions {
  std::string title = "bdfcar";
  int width = 1280, height = 720;
  bool vsync = true;          // SDL_GL_SetSwapInterval(1)
  bool fullscreen = false;    // desktop fullscreen
  // MSAA samples; falls back to none if unsupported. -1: 4 on a GPU, none on
  // software GL (llvmpipe pays for every sample: the proving ground drew at
  // 72 ms a frame with 4, 26 ms without).
  int multisample = -1;
  // Of the width and height, the resolution the world is drawn at (the HUD
  // always at full): 1 full, down to 0.5; 0: on a GPU chosen every few frames
  // to keep 30 fps (render/resolution_governor.h), on software GL full (its
  // stretch over the window costs what the fewer pixels save).
  double renderScale = 1;
};

class Window {
 public:
  // Opens the window (initialises SDL's video subsystem); throws RenderError with SDL's message.
  Window(Scene& scene, const WindowOptions& options = {});
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Draws the scene's current state and swaps buffers; if capture is non-null the
  // picture is read back (glReadPixels) before the swap. Throws on an all-black capture.
  void present(Frame* capture = nullptr);
  // Writes the next presented frame to a PNG file.
  void screenshotNextFrame(const std::string& pngPath);

  // Makes the GL context current in no thread, so that another thread may
  // present(); the window is created on the main thread (SDL's rule), the
  // drawing can run on a render thread. Call it from the thread that last
  // presented (or created the window) before another thread presents.
  void releaseContext();
  // Drains the window's quit, window and mouse events (main thread, after
  // input/ pumped the queue); leaves keyboard and device events alone.
  WindowEvents takeEvents();

  int width() const;   // drawable size in pixels, as of the last present()
  int height() const;
  const std::string& glRenderer() const;
  double worldScale() const;  // the scale the last frame's world was drawn at
  int samples() const;  // multisampling samples of the context made (0: none)
  void setTitle(const std::string& title);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bdfcar::render
