// Seeded rough-road waves: the random part of a generated road, drawn once at load.
#include <cmath>
#include <numbers>
#include <random>

#include "terrain/road_surface.h"
#include "portable_math.h"

namespace bdfcar::terrain {

// Wavelengths log-spaced from wavelengthMin to wavelengthMax; each wave stands
// for a band dn ~ n of spatial frequency n = 1/wavelength, so a displacement
// PSD ~ n^-2 (ISO 8608) gives it variance ~ n^-2 * n, amplitude ~ sqrt(wavelength).
// Directions uniform in [0, pi), phases uniform in [0, 2 pi); amplitudes
// scaled so that the RMS height sqrt(sum a^2 / 2) equals rmsHeight.
void makeRoughWaves(RoughPatch& patch) {
  std::mt19937_64 rng(patch.seed);
  // A double in [0, 1) from the top 53 bits: the standard fixes mt19937_64's
  // output but not uniform_real_distribution's, so convert by hand.
  auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const int n = patch.waveCount;
  patch.waves.clear();
  patch.waves.reserve(n);
  double sumSquares = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = n > 1 ? static_cast<double>(i) / (n - 1) : 0.5;
    const double wavelength = patch.wavelengthMin * pm::pow(patch.wavelengthMax / patch.wavelengthMin, t);
    const double direction = std::numbers::pi * uniform();
    const double phase = 2.0 * std::numbers::pi * uniform();
    const double k = 2.0 * std::numbers::pi / wavelength;
    patch.waves.push_back({k * pm::cos(direction), k * pm::sin(direction), std::sqrt(wavelength), phase});
    sumSquares += wavelength;
  }
  const double scale = n > 0 ? patch.rmsHeight * std::sqrt(2.0 / sumSquares) : 0.0;
  for (RoughWave& w : patch.waves) w.amplitude *= scale;
}

}  // namespace bdfcar::terrain
