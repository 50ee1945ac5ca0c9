// The road reader (physics/terrain/road_file.h readRoadSurface) straight on
// parsed TOML text, then both builders (road_surface.h): the road as a mesh
// and as a heightfield, whatever `build` the file names. loadTerrain reaches
// the same code through one builder only (fuzz_terrain).
#include "fuzz_common.h"
#include "terrain/road_file.h"
#include "terrain/road_surface.h"
#include "terrain/terrain_data.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  bdfcar::fuzz::expectOnlyDocumentedErrors([&] {
    bdfcar::config::Table top = bdfcar::config::parseTomlText(text, "road.toml");
    const bdfcar::terrain::RoadSurface road = bdfcar::terrain::readRoadSurface(top);
    bdfcar::terrain::TerrainData mesh, heightfield;
    bdfcar::terrain::buildRoadMesh(road, mesh);
    bdfcar::terrain::buildRoadHeightfield(road, heightfield);
  });
  return 0;
}
