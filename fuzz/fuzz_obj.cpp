// The Wavefront OBJ reader of terrain meshes (physics/terrain/obj_file.h).
#include "fuzz_common.h"
#include "terrain/obj_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = bdfcar::fuzz::writeCase(data, size, "mesh.obj");
  bdfcar::fuzz::expectOnlyDocumentedErrors([&] { (void)bdfcar::terrain::readObj(path); });
  return 0;
}
