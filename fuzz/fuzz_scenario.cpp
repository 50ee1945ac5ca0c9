// Scenario files (physics/scenario/scenario_spec.h loadScenarioFile). The
// input lies in <scratch>/case/, so the shipped "../vehicles/sedan.toml" and
// "../terrain/flat.toml" resolve to the real assets (see fuzz_common.h).
#include "fuzz_common.h"
#include "scenario/scenario_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = bdfcar::fuzz::writeCase(data, size, "scenario.toml");
  bdfcar::fuzz::expectOnlyDocumentedErrors([&] { (void)bdfcar::scenario::loadScenarioFile(path); });
  return 0;
}
