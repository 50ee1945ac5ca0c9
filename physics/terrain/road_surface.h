// A road described by a few parameters instead of a mesh file: a flat base
// z = 0 over a rectangle, plus bumps / curbs / potholes, ramps, seeded rough
// patches and washboard corrugations whose heights add. Built at load into a triangle mesh (exact: steps become
// vertical faces, slopes keep their breakpoints) or a uniform heightfield
// (steps become one-cell slopes). Deterministic: same parameters, same bits.
#pragma once

#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// A bump across [x, x + length] x [yMin, yMax].
struct Bump {
  enum class Profile { Step, Cosine };
  Profile profile = Profile::Step;  // Step: a block with vertical faces (curb, kerb, sidewalk);
                                    // Cosine: a smooth hump height/2 (1 - cos(2 pi (x - x0) / length))
  double x = 0.0;                   // start along x, m
  double length = 0.3;              // along x, m
  double height = 0.1;              // m (negative: a pothole / dip)
  double yMin = -kUnbounded, yMax = kUnbounded;  // lateral extent, m
};

// A wedge rising along +x at `angle` to `height`, a flat top, then a drop
// (vertical at dropAngle = pi/2: the lip of a jump).
struct Ramp {
  double x = 0.0;                           // foot of the rising face, m
  double angle = 0.1;                       // slope of the rising face, rad, in (0, pi/2)
  double height = 0.3;                      // m
  double topLength = 0.0;                   // flat top, m
  double dropAngle = std::numbers::pi / 2;  // slope of the falling face, rad, in (0, pi/2]
  double yMin = -kUnbounded, yMax = kUnbounded;
};

// One plane wave of a rough patch: amplitude * cos(kx x + ky y + phase).
struct RoughWave {
  double kx = 0, ky = 0;   // wave vector, rad/m
  double amplitude = 0;    // m
  double phase = 0;        // rad
};

// A seeded random rough surface over xMin <= x <= xMax (full width): a sum of
// plane waves with log-spaced wavelengths, random directions and phases, and a
// displacement spectrum ~ n^-2 as in ISO 8608; faded in and out over `fade`.
struct RoughPatch {
  std::uint64_t seed = 1;
  double xMin = 0.0, xMax = 100.0;  // m
  double rmsHeight = 0.01;          // m, of the full-amplitude (unfaded) surface
  double wavelengthMin = 0.5, wavelengthMax = 20.0;  // m
  int waveCount = 64;
  double fade = 2.0;                // m, smooth taper at both ends
  std::vector<RoughWave> waves{};   // filled by makeRoughWaves
};

// A washboard: ridges across the road at a fixed wavelength,
// height/2 (1 - cos(2 pi (x - xMin) / wavelength)), faded in and out over
// `fade` (so the surface joins the flat road without a step).
struct Corrugation {
  double xMin = 0.0, xMax = 100.0;  // m
  double wavelength = 0.7;          // m
  double height = 0.02;             // peak to trough, m
  double fade = 2.0;                // m
  double yMin = -kUnbounded, yMax = kUnbounded;
};

struct RoadSurface {
  double xMin = -50, xMax = 250, yMin = -10, yMax = 10;  // extent of the surface, m
  double cell = 0.25;  // heightfield spacing; also the sampling step of smooth features in a mesh, m
  std::vector<Bump> bumps{};
  std::vector<Ramp> ramps{};
  std::vector<RoughPatch> rough{};
  std::vector<Corrugation> corrugations{};
};

// Fill patch.waves deterministically from patch.seed (std::mt19937_64, whose
// output sequence the C++ standard fixes).
void makeRoughWaves(RoughPatch& patch);

// Height of the road at (x, y), m. Where a step makes it jump, sideX / sideY
// (+1 or -1) pick the limit from above or below along that axis.
double roadHeight(const RoadSurface& road, double x, double y, int sideX = +1, int sideY = +1);

// Triangle mesh of the road: a rectilinear grid through every feature edge
// (doubled at steps, giving vertical faces); smooth features sampled at
// <= cell. Fills data.vertices / data.triangles and sets kind = Mesh.
void buildRoadMesh(const RoadSurface& road, TerrainData& data);

// Uniform heightfield of the road with spacing `cell` from (xMin, yMin).
// Fills rows, cols, x0, y0, dx, dy, heights and sets kind = Heightfield.
void buildRoadHeightfield(const RoadSurface& road, TerrainData& data);

}  // namespace bdfcar::terrain
