#include "render/gl_check.h"

#include <dlfcn.h>

#include "render/frame.h"

namespace bdfcar::render {

// Looks the symbol up in the global scope, as the dynamic linker binds gl* calls.
std::string glSymbolProvider(const char* symbol) {
  void* address = dlsym(RTLD_DEFAULT, symbol);
  Dl_info info{};
  if (!address || !dladdr(address, &info) || !info.dli_fname) return "";
  return info.dli_fname;
}

// A null GL_RENDERER means no current context, or calls going to a library without one.
void requireGlContext(const unsigned char* renderer, const std::string& backend) {
  if (renderer && renderer[0] != '\0') return;
  const std::string provider = glSymbolProvider();
  throw RenderError(backend + ": glGetString(GL_RENDERER) is null, so there is no usable GL context (gl* resolve to " +
                    (provider.empty() ? std::string("nothing") : provider) +
                    "). Headless: libOSMesa must precede libGL/libOpenGL in the executable's NEEDED list "
                    "(link bdfcar_render_headless; check with readelf -d).");
}

}  // namespace bdfcar::render
