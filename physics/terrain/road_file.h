// The tables of a `kind = "road"` terrain file, read into a RoadSurface and
// built into mesh or heightfield data (internal to the terrain loader).
#pragma once

#include "config/toml_reader.h"
#include "terrain/road_surface.h"

namespace bdfcar::terrain {

// Reads [surface], [[bumps]], [[ramps]] and [[rough]] of the top-level table
// (build stays with the caller); errors are config::ConfigError.
RoadSurface readRoadSurface(config::Table& top);

}  // namespace bdfcar::terrain
