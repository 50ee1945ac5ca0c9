// `bdfcar input`: lists the input devices and shows live raw axis / button
// values and the mapped controls in the terminal, for calibrating mapping
// files; `--calibrate` writes one from a capture, `--ffb-test` pushes the
// wheel gently left and right.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "input/mapping.h"

namespace bdfcar::input {

// The longest --seconds / --interval accepted (about 11 days): longer is a typo,
// and 1e300 s would overflow the tick count.
constexpr double kMaxMonitorSeconds = 1e6;

// --calibrate: the capture's length when --seconds is not given, the still
// reading at its start (each axis's rest), and the shortest capture accepted.
constexpr double kCalibrationSeconds = 20.0;
constexpr double kCalibrationStillSeconds = 1.0;
constexpr double kCalibrationMinSeconds = 2.0;

struct MonitorOptions {
  double seconds = 0.0;        // how long to show live values; 0: until Ctrl-C (--calibrate: kCalibrationSeconds)
  double printInterval = 0.1;  // seconds between printed lines
  bool listOnly = false;       // list devices and mapping files, then return
  std::filesystem::path mappingDir = defaultMappingDir();
  std::string deviceFilter;    // only devices whose name contains this
  std::FILE* out = stdout;
  std::filesystem::path calibrateOut;  // --calibrate: the mapping file to write
};

// Runs the monitor; returns the process exit code (0 ok, 1 bad mapping, bad
// seconds / interval (non-finite or outside [0, kMaxMonitorSeconds]) or SDL failure).
int runInputMonitor(const MonitorOptions& options);

// `--calibrate`: captures the driving device's (else the first one's) raw axes
// for `seconds`, the first kCalibrationStillSeconds still, and writes the
// mapping calibrateAxes finds (calibration.h) to calibrateOut, saying what was
// assigned. Returns 0 (written; or no device: says so and writes nothing, as
// runInputMonitor), 1 (bad mapping folder, seconds outside
// [kCalibrationMinSeconds, kMaxMonitorSeconds], no steering axis found, the
// device unplugged), 5 (the file could not be written) or 130 (Ctrl-C: nothing
// written).
int runInputCalibration(const MonitorOptions& options);

// `--ffb-test`: the force-feedback test's pushes (force_feedback.h) on the
// driving device through its mapping's gain and invert, each phase printed
// as it begins. Returns 0 (done; or no device, or none with force feedback
// opened: says which and why), 1 (bad mapping folder or SDL failure) or 130 (Ctrl-C).
int runForceFeedbackTest(const MonitorOptions& options);

}  // namespace bdfcar::input
