// `bdfcar input`: list input devices and show live values for calibration;
// --calibrate writes a mapping file from a capture, --ffb-test pushes the wheel.
#include "input/monitor.h"

#include "commands.h"

namespace bdfcar::app {

namespace {

struct InputArgs {
  input::MonitorOptions options;
  bool calibrate = false, ffbTest = false;  // the mode; neither: the live monitor
};

}  // namespace

void addInputCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "input",
      "List wheels, game controllers and joysticks and show live axis / button values for calibration; "
      "--calibrate writes a mapping file from a capture, --ffb-test tries the force feedback. With no device "
      "each says so and exits 0");
  auto a = std::make_shared<InputArgs>();
  input::MonitorOptions& o = a->options;
  // The bounds of input::runInputMonitor (monitor.h); NaN and inf are refused in main.
  cmd->add_option("--seconds", o.seconds,
                  "Show live values this long, then exit (0: until Ctrl-C); with --calibrate the capture's length "
                  "(default 20, at least 2)")
      ->check(CLI::Range(0.0, input::kMaxMonitorSeconds));
  cmd->add_option("--interval", o.printInterval, "Seconds between printed lines")
      ->check(CLI::Range(0.01, input::kMaxMonitorSeconds));
  CLI::Option* list = cmd->add_flag("--list", o.listOnly, "List the devices and their mapping files, then exit");
  cmd->add_option("--mappings", o.mappingDir, "Folder of mapping files (*.toml)")->check(CLI::ExistingDirectory);
  cmd->add_option("--device", o.deviceFilter, "Only devices whose name contains this text");
  CLI::Option* calibrate = cmd->add_flag(
      "--calibrate", a->calibrate,
      "Capture the driving device's axes (1 s still: the rests; then turn the wheel lock to lock and press the "
      "throttle, brake, clutch, handbrake in that order) and write a mapping file to --out, printing what it "
      "assigned; exit 1 when no axis turned both ways (no steering), 5 when the file cannot be written");
  CLI::Option* out = cmd->add_option("--out", o.calibrateOut, "With --calibrate: the mapping file to write (FILE.toml)");
  CLI::Option* ffb = cmd->add_flag(
      "--ffb-test", a->ffbTest,
      "Push the driving device's wheel gently left, then right (3.2 s) through SDL haptic with its mapping's "
      "force-feedback gain and invert, printing each push; a device without force feedback says so (exit 0)");
  calibrate->needs(out)->excludes(ffb)->excludes(list);
  out->needs(calibrate);
  ffb->excludes(list);
  commands.push_back({cmd, [a] {
                        if (a->calibrate) return input::runInputCalibration(a->options);
                        if (a->ffbTest) return input::runForceFeedbackTest(a->options);
                        return input::runInputMonitor(a->options);
                      }});
}

}  // namespace bdfcar::app
