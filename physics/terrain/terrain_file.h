// Loading a terrain asset (assets/terrain/*.toml) into TerrainData.
//
// Top-level keys: name (string, optional), kind ("plane" | "mesh" |
// "heightfield" | "road"), friction (number in (0, 2]), an optional
// [markings] table (road painting for the renderer: start_x, end_x,
// centre_y, lanes, lane_width), optional [[friction_patches]] (x_min, x_max,
// y_min, y_max, each optional and unbounded by default, and friction: the
// friction a tyre reads where its contact point is inside; the last patch
// listed wins), and the tables of the kind:
//   plane:       [plane] point = [x, y, z], normal = [x, y, z]
//   mesh:        [mesh] obj = "file.obj" (relative to the .toml; triangles,
//                quads or convex polygons, z up, metres), offset = [x, y, z]
//   heightfield: [heightfield] x0, y0, dx, dy, heights = [[row 0 along +x], [row 1], ...]
//                (rows step along +y)
//   road:        build = "mesh" | "heightfield", [surface] x_min, x_max,
//                y_min, y_max, cell; [[bumps]] (a negative height is a
//                pothole), [[ramps]], [[rough]], [[corrugations]] (washboard:
//                x_min, x_max, wavelength, height, fade, y_min, y_max)
//                (see road_surface.h and the assets for their keys)
// Every error is a TerrainFileError whose message names the file, the line,
// the key and what was expected; unknown keys are errors too.
#pragma once

#include <stdexcept>
#include <string>

#include "terrain/terrain_data.h"

namespace bdfcar::terrain {

struct TerrainFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads, checks and builds the terrain described by a TOML file.
TerrainData loadTerrain(const std::string& tomlPath);

}  // namespace bdfcar::terrain
