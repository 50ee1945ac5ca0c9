// The process's own arguments and the sibling headless program: `bdfcar`
// (on screen, glvnd GL) hands headless work to `bdfcar-headless` (OSMesa
// linked first), because the two GL stacks cannot share one process.
#pragma once

#include <string>

namespace bdfcar::app {

void setProcessArguments(int argc, char** argv);
// Replaces this process with bdfcar-headless run with the same arguments
// (from the same folder as this executable). Returns only on failure, with why.
std::string execHeadless();
// True when a display server may be reachable (DISPLAY or WAYLAND_DISPLAY set).
bool displayConfigured();

}  // namespace bdfcar::app
