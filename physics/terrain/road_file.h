// The tables of a `kind = "road"` terrain file, read into a RoadSurface and
// built into mesh or heightfield data (internal to the terrain loader).
#pragma once

#include "terrain/road_surface.h"
#include "terrain/toml_fields.h"

namespace bdfcar::terrain {

// Reads build, [surface], [[bumps]], [[ramps]] and [[rough]] of the top-level table.
RoadSurface readRoadSurface(const toml_fields::Table& top);

}  // namespace bdfcar::terrain
