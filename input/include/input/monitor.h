// `bdfcar input`: lists the input devices and shows live raw axis / button
// values and the mapped controls in the terminal, for calibrating mapping files.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "input/mapping.h"

namespace bdfcar::input {

// The longest --seconds / --interval accepted (about 11 days): longer is a typo,
// and 1e300 s would overflow the tick count.
constexpr double kMaxMonitorSeconds = 1e6;

struct MonitorOptions {
  double seconds = 0.0;        // how long to show live values; 0: until Ctrl-C
  double printInterval = 0.1;  // seconds between printed lines
  bool listOnly = false;       // list devices and mapping files, then return
  std::filesystem::path mappingDir = defaultMappingDir();
  std::string deviceFilter;    // only devices whose name contains this
  std::FILE* out = stdout;
};

// Runs the monitor; returns the process exit code (0 ok, 1 bad mapping, bad
// seconds / interval (non-finite or outside [0, kMaxMonitorSeconds]) or SDL failure).
int runInputMonitor(const MonitorOptions& options);

}  // namespace bdfcar::input
