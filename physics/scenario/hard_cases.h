// The hard cases the simulator must survive (curb strike, jump, rough road,
// spin-out), as edits of the project's scenarios: one list for the tests
// (tests/test_scenario.cpp) and for the report (docs/RESULTS.md, 4b).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scenario/scenario_spec.h"

namespace bdfcar::scenario {

struct HardCase {
  std::string name;          // starts with what it is: "curb ...", "jump ...", "rough ...", "spin ..."
  std::string scenarioFile;  // under assets/scenarios
  std::string edits;         // the edits in words, as a scenario file would hold them
  std::function<void(ScenarioSpec&)> edit;
};

// The cases; terrain files are looked up under assetDir/terrain.
std::vector<HardCase> hardCases(const std::string& assetDir);

}  // namespace bdfcar::scenario
