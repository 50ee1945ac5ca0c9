// `bdfcar input --ffb-test`: the force-feedback test's gentle pushes
// (force_feedback.h) through the same path as driving
// (InputSystem::setSteeringTorque: the mapping's gain and invert, SDL haptic).
#include <filesystem>

#include "input/force_feedback.h"
#include "input/monitor.h"
#include "input_command.h"

namespace bdfcar::input {
namespace {

// Why a device has no force feedback here: its file, or the device (or access to it).
void sayNoForceFeedback(std::FILE* out, const DeviceStatus& device, const DeviceMapping& mapping) {
  const std::string file = std::filesystem::path(device.mappingFile).filename().string();
  if (!mapping.forceFeedback.enabled)
    std::fprintf(out,
                 "'%s': its mapping %s does not turn force feedback on (add [force_feedback], "
                 "assets/input/README.md): nothing to test\n",
                 device.name.c_str(), file.c_str());
  else
    std::fprintf(out,
                 "'%s' has no force feedback here: SDL offers it no constant-force effect (no motor, or this user may "
                 "not write /dev/input/event*): nothing to test\n",
                 device.name.c_str());
}

}  // namespace

// The pushes, tick by tick, each phase announced as it begins.
int runForceFeedbackTest(const MonitorOptions& o) {
  return withCommandDevice(o, "no force feedback to test", [&](InputSystem& input, const DeviceStatus& device) {
    const DeviceMapping mapping = loadMappingFile(device.mappingFile);
    if (!device.forceFeedback) {
      sayNoForceFeedback(o.out, device, mapping);
      return 0;
    }
    if (!device.active) {  // setSteeringTorque feels through the driving device only
      std::fprintf(o.out, "'%s' has force feedback but cannot drive (its mapping binds no steering axis it has): nothing to test\n",
                   device.name.c_str());
      return 0;
    }
    const std::string file = std::filesystem::path(device.mappingFile).filename().string();
    std::fprintf(o.out,
                 "force-feedback test on '%s' (%s: gain %g, invert %s): gentle pushes of at most %g of the driving "
                 "torque's full feel; hold the wheel lightly\n",
                 device.name.c_str(), file.c_str(), mapping.forceFeedback.gain,
                 mapping.forceFeedback.invert ? "true" : "false", kForceFeedbackTestCommand);
    int phase = -1;
    for (long i = 0;; ++i) {
      const double t = i * kCommandTick;
      const int now = forceFeedbackTestPhase(t);
      if (now < 0) break;
      if (now != phase) {
        const ForceFeedbackTestPhase& p = forceFeedbackTestPhases()[now];
        std::fprintf(o.out, "t=%5.2f  %s (command %+.2f -> %+.2f over %g s)\n", t, p.what, p.from, p.to, p.seconds);
        std::fflush(o.out);
        phase = now;
      }
      waitTick(input);
      input.setSteeringTorque(forceFeedbackTestCommand(t));
      if (quitRequested()) {
        input.setSteeringTorque(0.0);
        std::fprintf(stderr, "stopped by SIGINT: force released\n");
        return kExitInterrupted;
      }
    }
    input.setSteeringTorque(0.0);
    std::fprintf(o.out,
                 "done, force released. Did the wheel turn left first, then right? If it went right first, set "
                 "invert = true under [force_feedback] in %s; too weak or too strong: its gain.\n",
                 file.c_str());
    return 0;
  });
}

}  // namespace bdfcar::input
