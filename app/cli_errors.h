// Runs a command body and turns the errors bad input can raise into a clear
// message on stderr and a non-zero exit code (never a crash).
#pragma once

#include <functional>

namespace bdfcar::app {

// Exit codes: 0 ok, 1 bad input (file, key, value), 3 simulation diverged or failed.
int reportErrors(const std::function<int()>& body);

}  // namespace bdfcar::app
