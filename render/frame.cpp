#include "render/frame.h"

#include <algorithm>

namespace bdfcar::render {

// Frame of the given size, filled with zeros.
Frame makeFrame(int width, int height) {
  if (width <= 0 || height <= 0)
    throw RenderError("frame size must be positive, got " + std::to_string(width) + "x" + std::to_string(height));
  Frame f;
  f.width = width;
  f.height = height;
  f.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
  return f;
}

// True if every pixel's RGB is below the threshold.
bool isAllBlack(const Frame& frame, int threshold) {
  for (std::size_t i = 0; i + 3 < frame.rgba.size(); i += 4)
    if (frame.rgba[i] >= threshold || frame.rgba[i + 1] >= threshold || frame.rgba[i + 2] >= threshold) return false;
  return true;
}

// Throws if the frame is all black.
void requireNotBlack(const Frame& frame, const std::string& what) {
  if (isAllBlack(frame))
    throw RenderError(what + ": the frame is all black (the GL context draws nothing; "
                             "for OSMesa check that libOSMesa precedes libGL in the executable's NEEDED list)");
}

// Reverses the row order in place.
void flipRows(Frame& frame) {
  const std::size_t stride = static_cast<std::size_t>(frame.width) * 4;
  for (int top = 0, bottom = frame.height - 1; top < bottom; ++top, --bottom)
    std::swap_ranges(frame.rgba.begin() + top * stride, frame.rgba.begin() + (top + 1) * stride,
                     frame.rgba.begin() + bottom * stride);
}

}  // namespace bdfcar::render
