// What the pause menu's "drive them here" needs (issue 30): the cars and
// fidelities a drive offers, and the outputs of each drive after the first,
// named so that none replaces another's.
#pragma once

#include <string>
#include <vector>

#include "scenario/scenario_spec.h"
#include "session/pause_menu.h"

namespace bdfcar::app {

// The N-th drive's output: PATH for the first, then PATH-N with the
// extension kept (run.csv, run-2.csv), or the first higher N whose file does
// not exist yet. An empty path stays empty (no such output).
std::string driveOutput(const std::string& path, int drive);

// The shipped vehicles (assets/vehicles/*.toml, sorted; the scenario's own
// first where it is not one of them) and the ladder's rungs with auto, the
// scenario's current ones chosen; carFiles[i] is the file of menu.cars[i].
struct DrivePicks {
  MenuPicks menu;
  std::vector<std::string> carFiles;
};
DrivePicks drivePicks(const scenario::ScenarioSpec& spec);

}  // namespace bdfcar::app
