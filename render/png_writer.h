// PNG files from frames with libpng. Default zlib compression costs ~10x the
// render time of a frame, so the level defaults to 1 (fastest).
#pragma once

#include <string>

#include "render/frame.h"

namespace bdfcar::render {

// Writes the frame as an 8-bit RGB PNG (alpha dropped); throws RenderError on failure.
// compressionLevel: zlib level 0 (none) .. 9 (smallest, slowest).
void writePng(const std::string& path, const Frame& frame, int compressionLevel = 1);

}  // namespace bdfcar::render
