// The [track] table of a `kind = "track"` terrain file, read into a Track
// (internal to the terrain loader).
#pragma once

#include "config/toml_reader.h"
#include "terrain/track.h"

namespace bdfcar::terrain {

// Reads [track] of the top-level table; `surface` is the file's material.
// Errors are config::ConfigError naming file, line and key; a circuit that
// does not close is one on `track.closed`.
Track readTrack(config::Table track, Material surface);

}  // namespace bdfcar::terrain
