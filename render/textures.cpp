#include "render/textures.h"

#include <osg/Image>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

namespace bdfcar::render {
namespace {

constexpr int kSize = 256;

// Deterministic hash of a lattice point to [0, 1).
double latticeNoise(int x, int y, int seed) {
  std::uint32_t h = static_cast<std::uint32_t>(x) * 374761393u + static_cast<std::uint32_t>(y) * 668265263u +
                    static_cast<std::uint32_t>(seed) * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return ((h ^ (h >> 16)) & 0xffffff) / double(0x1000000);
}

// Smoothly interpolated lattice noise with period `cells` in both directions (tileable).
double valueNoise(double x, double y, int cells, int seed) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
  auto at = [&](int i, int j) { return latticeNoise(((i % cells) + cells) % cells, ((j % cells) + cells) % cells, seed); };
  const double a = at(x0, y0) + sx * (at(x0 + 1, y0) - at(x0, y0));
  const double b = at(x0, y0 + 1) + sx * (at(x0 + 1, y0 + 1) - at(x0, y0 + 1));
  return a + sy * (b - a);
}

// Sum of octaves of tileable value noise at texel (i, j), in [0, 1].
double fractalNoise(int i, int j, int baseCells, int octaves, int seed) {
  double sum = 0, amp = 1, total = 0;
  for (int o = 0, cells = baseCells; o < octaves; ++o, cells *= 2, amp *= 0.5) {
    sum += amp * valueNoise(double(i) * cells / kSize, double(j) * cells / kSize, cells, seed + o);
    total += amp;
  }
  return sum / total;
}

// Repeating, mipmapped texture from a per-texel colour function.
osg::ref_ptr<osg::Texture2D> makeTexture(const std::function<osg::Vec3(int, int)>& colour) {
  osg::ref_ptr<osg::Image> image = new osg::Image;
  image->allocateImage(kSize, kSize, 1, GL_RGB, GL_UNSIGNED_BYTE);
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      const osg::Vec3 c = colour(i, j);
      unsigned char* p = image->data(i, j);
      for (int k = 0; k < 3; ++k) p[k] = static_cast<unsigned char>(std::lround(std::clamp(c[k], 0.0f, 1.0f) * 255));
    }
  osg::ref_ptr<osg::Texture2D> tex = new osg::Texture2D(image.get());
  tex->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);
  tex->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
  // Bilinear within the nearest mip level: half the texel fetches of trilinear.
  tex->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR_MIPMAP_NEAREST);
  tex->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
  // No anisotropic filtering: on llvmpipe it costs seconds per frame on a large ground plane.
  return tex;
}

}  // namespace

// Grass: two greens mixed by large-scale noise, plus fine speckle.
osg::ref_ptr<osg::Texture2D> grassTexture() {
  return makeTexture([](int i, int j) {
    const double broad = fractalNoise(i, j, 4, 3, 11), fine = fractalNoise(i, j, 64, 2, 29);
    const osg::Vec3 dry(0.47f, 0.55f, 0.28f), lush(0.26f, 0.45f, 0.17f);
    const osg::Vec3 base = dry * float(broad) + lush * float(1 - broad);
    return base * float(0.8 + 0.4 * fine);
  });
}

// Asphalt: dark grey with fine aggregate speckle.
osg::ref_ptr<osg::Texture2D> asphaltTexture() {
  return makeTexture([](int i, int j) {
    const double grain = fractalNoise(i, j, 128, 2, 5), patch = fractalNoise(i, j, 4, 2, 7);
    const float g = float(0.26 + 0.07 * grain + 0.04 * patch);
    return osg::Vec3(g, g, g * 1.03f);
  });
}

}  // namespace bdfcar::render
