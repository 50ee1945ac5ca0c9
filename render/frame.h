// A rendered picture in memory: 8-bit RGBA, top row first, no padding.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace bdfcar::render {

struct Frame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // (height x width x 4), row 0 = top of the picture

  const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

// What one frame drew: the drawables the cull kept and their triangles.
struct DrawLoad {
  unsigned drawables = 0;
  unsigned long triangles = 0;
};

// Any failure to set up or run a renderer, or to write its output.
struct RenderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Frame of the given size, filled with zeros.
Frame makeFrame(int width, int height);

// True if every pixel's RGB is below `threshold` (a context that draws nothing).
bool isAllBlack(const Frame& frame, int threshold = 8);

// Throws RenderError if the frame is all black: a silent GL failure, never a valid picture.
void requireNotBlack(const Frame& frame, const std::string& what);

// Reverses the row order in place (GL reads bottom row first).
void flipRows(Frame& frame);

}  // namespace bdfcar::render
