// `bdfcar input --calibrate`: captures a device's raw axes while the person
// holds still, then turns the wheel lock to lock and presses each pedal, and
// writes the mapping calibrateAxes finds (calibration.h).
#include <cmath>
#include <fstream>

#include "input/calibration.h"
#include "input/monitor.h"
#include "input_command.h"

namespace bdfcar::input {
namespace {

constexpr int kExitOutputFailed = 5;  // README, "Exit codes": an output could not be written

// The file's opening comment: where it came from and what to check.
std::vector<std::string> fileComment(const DeviceStatus& device, double seconds, const Calibration& cal) {
  char capture[160];
  std::snprintf(capture, sizeof capture, "rests from the still reading of its first %g s, ends from a %g s capture",
                kCalibrationStillSeconds, seconds);
  std::vector<std::string> lines = {"Calibrated by `bdfcar input --calibrate` from '" + device.name + "'",
                                    std::string("(") + capture + ").",
                                    "Check it with `bdfcar input`: steering + when turned left, each pedal 0 "
                                    "released .. 1 fully down.",
                                    "Actions, force feedback, deadzones, curves and rotation_deg are those of " +
                                        std::filesystem::path(device.mappingFile).filename().string() + ".",
                                    "", "What the capture found:"};
  for (const std::string& line : cal.report) lines.push_back("  " + line);
  return lines;
}

// Writes the text whole or reports why not.
bool writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  return static_cast<bool>(out);
}

// The capture: a row of raw axis values per tick. Returns 0 with the rows, or the exit code.
int captureAxes(InputSystem& input, const DeviceStatus& device, long ticks, long still, std::FILE* out,
                std::vector<std::vector<int>>& samples) {
  std::fprintf(out,
               "calibrating '%s' for %g s. Now, for %g s: hands off the wheel (straight ahead), feet off the "
               "pedals: each axis's rest.\n",
               device.name.c_str(), ticks * kCommandTick, still * kCommandTick);
  std::fflush(out);
  for (long i = 1; i <= ticks; ++i) {
    waitTick(input);
    const std::vector<DeviceStatus> now = input.devices();
    const DeviceStatus* d = findStatus(now, device.instanceId);
    if (!d) {
      std::fprintf(stderr, "bdfcar input: '%s' was unplugged during the capture: nothing written\n",
                   device.name.c_str());
      return 1;
    }
    samples.push_back(d->rawAxes);
    if (i == still) {
      std::fprintf(out,
                   "now: turn the wheel to full left and full right lock, then press the throttle fully, then the "
                   "brake, then the clutch (if any), then pull the handbrake (if any), one at a time: the order "
                   "names the pedals (%g s left)\n",
                   (ticks - i) * kCommandTick);
      std::fflush(out);
    }
    if (quitRequested()) {
      std::fprintf(stderr, "stopped by SIGINT during the capture: nothing written\n");
      return kExitInterrupted;
    }
  }
  return 0;
}

}  // namespace

// Capture, assignment, file.
int runInputCalibration(const MonitorOptions& o) {
  const double seconds = o.seconds > 0.0 ? o.seconds : kCalibrationSeconds;
  if (!(seconds >= kCalibrationMinSeconds && seconds <= kMaxMonitorSeconds)) {
    std::fprintf(stderr, "bdfcar input: --calibrate needs --seconds in [%g, %g] (the still reading alone takes %g s)\n",
                 kCalibrationMinSeconds, kMaxMonitorSeconds, kCalibrationStillSeconds);
    return 1;
  }
  if (o.calibrateOut.empty()) {
    std::fprintf(stderr, "bdfcar input: --calibrate needs --out FILE.toml\n");
    return 1;
  }
  return withCommandDevice(o, "nothing to calibrate, nothing written", [&](InputSystem& input, const DeviceStatus& device) {
    DeviceMapping base = loadMappingFile(device.mappingFile);
    base.nameContains = {device.name};  // the file claims this device, before any generic one
    const long ticks = std::lround(seconds / kCommandTick), still = std::lround(kCalibrationStillSeconds / kCommandTick);
    std::vector<std::vector<int>> samples;
    if (const int code = captureAxes(input, device, ticks, still, o.out, samples)) return code;
    const Calibration cal = calibrateAxes(samples, static_cast<int>(still), base);
    std::fprintf(o.out, "found:\n");
    for (const std::string& line : cal.report) std::fprintf(o.out, "  %s\n", line.c_str());
    if (cal.report.empty()) std::fprintf(o.out, "  no axis moved by %d raw counts or more\n", kCalibrationMinTravel);
    if (!cal.steeringFound) {
      std::fprintf(stderr,
                   "bdfcar input: no axis was turned both ways from its rest (by %d raw counts or more): no steering, "
                   "nothing written; calibrate again turning the wheel lock to lock\n",
                   kCalibrationMinTravel / 2);
      return 1;
    }
    if (!writeText(o.calibrateOut, mappingToml(cal.mapping, fileComment(device, seconds, cal)))) {
      std::fprintf(stderr, "error: %s: cannot write the mapping file\n", o.calibrateOut.string().c_str());
      return kExitOutputFailed;
    }
    std::fprintf(o.out,
                 "wrote %s as a %s mapping naming '%s'. Check what was assigned above: put the file in the mapping "
                 "folder (%s, or --mappings DIR) and watch `bdfcar input` while you steer and press each pedal.\n",
                 o.calibrateOut.string().c_str(), std::string(deviceKindName(base.kind)).c_str(), device.name.c_str(),
                 o.mappingDir.string().c_str());
    return 0;
  });
}

}  // namespace bdfcar::input
