// Terrain files (physics/terrain/terrain_file.h loadTerrain): plane, mesh
// (with its OBJ), heightfield and road kinds, each checked and built into
// TerrainData. A small square.obj sits next to the input for mesh files.
#include "fuzz_common.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char obj[] = "v -5 -5 0\nv 5 -5 0\nv 5 5 0\nv -5 5 0\nf 1 2 3 4\n";
  bdfcar::fuzz::writeCase(reinterpret_cast<const std::uint8_t*>(obj), sizeof obj - 1, "square.obj");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = bdfcar::fuzz::writeCase(data, size, "terrain.toml");
  bdfcar::fuzz::expectOnlyDocumentedErrors([&] { (void)bdfcar::terrain::loadTerrain(path); });
  return 0;
}
