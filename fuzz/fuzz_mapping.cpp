// Input mapping files (input/include/input/mapping.h parseMapping, from text).
// input::MappingError is their documented error.
#include "fuzz_common.h"
#include "input/mapping.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  bdfcar::fuzz::expectOnlyDocumentedErrors([&] {
    try {
      (void)bdfcar::input::parseMapping(text, "mapping.toml");
    } catch (const bdfcar::input::MappingError&) {
    }
  });
  return 0;
}
