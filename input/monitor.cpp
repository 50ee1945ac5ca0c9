// `bdfcar input`: device list and live raw values for calibrating mapping files.
#include "input/monitor.h"

#include <cmath>
#include <string>

#include "input/input_system.h"
#include "input_command.h"

namespace bdfcar::input {
namespace {

constexpr double kTick = kCommandTick;

// "[1 -2 3]" of a list of integers.
std::string listText(const std::vector<int>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) text += ' ';
    text += std::to_string(values[i]);
  }
  return text + "]";
}

// The names of the actions set in `c`, or "-".
std::string actionsText(const Controls& c) {
  std::string text;
  for (int a = 0; a < kActionCount; ++a)
    if (actionFlag(c, static_cast<Action>(a))) {
      if (!text.empty()) text += ',';
      text += actionName(static_cast<Action>(a));
    }
  return text.empty() ? "-" : text;
}

// Ors the actions of one tick into those seen since the last printed line.
void accumulateActions(const Controls& tick, Controls& seen) {
  for (int a = 0; a < kActionCount; ++a)
    if (actionFlag(tick, static_cast<Action>(a))) actionFlag(seen, static_cast<Action>(a)) = true;
}

// The device table printed at start.
void printDevices(std::FILE* out, const std::vector<DeviceStatus>& devices, const MonitorOptions& o) {
  std::fprintf(out, "input devices: %zu (mapping files from %s)\n", devices.size(), o.mappingDir.string().c_str());
  for (const DeviceStatus& d : devices)
    std::fprintf(out, "  #%d '%s'  %s  mapping %s  %zu axes  force feedback: %s%s\n", d.instanceId, d.name.c_str(),
                 std::string(deviceKindName(d.kind)).c_str(),
                 std::filesystem::path(d.mappingFile).filename().string().c_str(), d.rawAxes.size(),
                 d.forceFeedback ? "yes" : "no", d.active ? "  [drives]" : "");
  std::fprintf(out, "  keyboard: keys need the simulator's window, so they are not read here\n");
}

// One block of live values: raw per device, then the mapped controls.
void printLive(std::FILE* out, double t, const std::vector<DeviceStatus>& devices, const Controls& c,
               const Controls& actions) {
  for (const DeviceStatus& d : devices)
    std::fprintf(out, "t=%7.2f  '%s' axes %s buttons %s\n", t, d.name.c_str(), listText(d.rawAxes).c_str(),
                 listText(d.pressedButtons).c_str());
  char clutch[16] = "-";
  if (c.hasClutch) std::snprintf(clutch, sizeof clutch, "%.3f", c.clutch);
  std::fprintf(out, "t=%7.2f  -> %s: steering %+.3f throttle %.3f brake %.3f clutch %s  actions %s\n", t,
               std::string(deviceKindName(c.source)).c_str(), c.steering, c.throttle, c.brake, clutch,
               actionsText(actions).c_str());
  std::fflush(out);
}

}  // namespace

// Lists devices, then polls every 10 ms and prints at the chosen interval.
int runInputMonitor(const MonitorOptions& o) {
  // Checked here too (not only by the CLI): the tick counts below must fit a long.
  const auto inRange = [](double x, double lo) { return std::isfinite(x) && x >= lo && x <= kMaxMonitorSeconds; };
  if (!inRange(o.seconds, 0.0) || !inRange(o.printInterval, kTick)) {
    std::fprintf(stderr, "bdfcar input: --seconds must be in [0, %g] and --interval in [%g, %g] s\n", kMaxMonitorSeconds,
                 kTick, kMaxMonitorSeconds);
    return 1;
  }
  return withDevices(o, [&](InputSystem& input) {
    printDevices(o.out, input.devices(), o);
    if (o.listOnly) return 0;
    if (input.devices().empty()) {
      sayNoDevice(o.out, "no live values to show");  // the keyboard's zeros for ever would say nothing
      return 0;
    }
    const long ticks = o.seconds > 0.0 ? std::lround(o.seconds / kTick) : -1;  // -1: until Ctrl-C
    const long printEvery = std::max(1L, std::lround(o.printInterval / kTick));
    Controls seen;
    for (long i = 1; ticks < 0 || i <= ticks; ++i) {
      const Controls c = waitTick(input);
      accumulateActions(c, seen);
      if (i % printEvery == 0 || i == ticks) {
        printLive(o.out, i * kTick, input.devices(), c, seen);
        seen = Controls{};
      }
      if (quitRequested()) break;
    }
    return 0;
  });
}

}  // namespace bdfcar::input
