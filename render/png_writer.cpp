#include "render/png_writer.h"

#include <png.h>
#include <zlib.h>

#include <cstdio>
#include <memory>
#include <vector>

namespace bdfcar::render {
namespace {

// Throws from libpng's error callback instead of its default longjmp (unwinding through
// libpng is fine on x86-64, whose C code carries unwind tables).
[[noreturn]] void throwPngError(png_structp, png_const_charp message) { throw RenderError(std::string("libpng: ") + message); }

}  // namespace

// Encodes the frame with libpng at the given zlib level.
void writePng(const std::string& path, const Frame& frame, int compressionLevel) {
  if (frame.width <= 0 || frame.height <= 0 || frame.rgba.size() != static_cast<std::size_t>(frame.width) * frame.height * 4)
    throw RenderError("writePng(" + path + "): malformed frame");
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file) throw RenderError("writePng: cannot open " + path + " for writing");

  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, &throwPngError, nullptr);
  if (!png) throw RenderError("writePng: png_create_write_struct failed");
  png_infop info = png_create_info_struct(png);
  struct Cleanup {
    png_structp* p;
    png_infop* i;
    ~Cleanup() { png_destroy_write_struct(p, i); }
  } cleanup{&png, &info};
  if (!info) throw RenderError("writePng: png_create_info_struct failed");

  png_init_io(png, file.get());
  png_set_IHDR(png, info, static_cast<png_uint_32>(frame.width), static_cast<png_uint_32>(frame.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, compressionLevel);
  // One cheap filter instead of libpng's per-row search over all five: the
  // search costs more than it saves at low zlib levels.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, compressionLevel <= 3 ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
  // Run-length matches only at low levels: rendered frames are mostly flat
  // runs (sky, road) after the SUB filter; RLE finds those at a fraction of
  // deflate's cost for files about as small.
  if (compressionLevel <= 3) png_set_compression_strategy(png, Z_RLE);
  png_write_info(png, info);
  png_set_filler(png, 0, PNG_FILLER_AFTER);  // input rows are RGBA: skip the alpha byte

  std::vector<png_bytep> rows(static_cast<std::size_t>(frame.height));
  for (int y = 0; y < frame.height; ++y)
    rows[y] = const_cast<png_bytep>(frame.rgba.data() + static_cast<std::size_t>(y) * frame.width * 4);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  if (std::fflush(file.get()) != 0) throw RenderError("writePng: write error on " + path);
}

}  // namespace bdfcar::render
