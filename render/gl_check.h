// Start-up checks that a renderer really has a working GL context: a context
// that silently draws nothing (gl* bound to the wrong library) must be an
// error, never a black picture.
#pragma once

#include <string>

namespace bdfcar::render {

// File of the shared library that supplies `symbol` to this process ("" if unresolved).
std::string glSymbolProvider(const char* symbol = "glGetString");

// Throws RenderError unless `renderer` (glGetString(GL_RENDERER)) is non-null and
// non-empty; the message names the backend and the library gl* resolve to.
void requireGlContext(const unsigned char* renderer, const std::string& backend);

}  // namespace bdfcar::render
