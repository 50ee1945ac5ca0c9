// `bdfcar input`: list input devices and show live values for calibration.
#include "input/monitor.h"

#include "commands.h"

namespace bdfcar::app {

void addInputCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "input", "List wheels, game controllers and joysticks and show live axis / button values for calibration");
  auto options = std::make_shared<input::MonitorOptions>();
  // The bounds of input::runInputMonitor (monitor.h); NaN and inf are refused in main.
  cmd->add_option("--seconds", options->seconds, "Show live values this long, then exit (0: until Ctrl-C)")
      ->check(CLI::Range(0.0, input::kMaxMonitorSeconds));
  cmd->add_option("--interval", options->printInterval, "Seconds between printed lines")
      ->check(CLI::Range(0.01, input::kMaxMonitorSeconds));
  cmd->add_flag("--list", options->listOnly, "List the devices and their mapping files, then exit");
  cmd->add_option("--mappings", options->mappingDir, "Folder of mapping files (*.toml)")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--device", options->deviceFilter, "Only devices whose name contains this text");
  commands.push_back({cmd, [options] { return input::runInputMonitor(*options); }});
}

}  // namespace bdfcar::app
