// bdfcar-headless: rendering without a display server (OSMesa). libOSMesa is
// the first NEEDED library of this executable (checked at link time), so the
// gl* calls of OpenSceneGraph reach OSMesa, not glvnd.
#include <cstdio>

#include "cli_errors.h"
#include "commands.h"
#include "process.h"
#include "render/library_versions.h"

int main(int argc, char** argv) {
  using namespace bdfcar::app;
  setProcessArguments(argc, argv);
  CLI::App app{"bdfcar-headless: render bdfcar scenarios to frames and video without a display"};
  app.require_subcommand(0, 1);
  CommandList commands;
  addVersionCommand(app, commands, {bdfcar::render::osgVersion()});
  addHeadlessCommands(app, commands);
  requireFiniteNumbers(app);  // the same checks and exit codes as bdfcar (app/cli_errors.h)
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cliExitCode(app, e);
  }
  for (const Command& c : commands)
    if (c.cli->parsed()) return c.run();
  std::fprintf(stderr, "%s\nerror: name a command (see above)\n", app.help().c_str());
  return 2;
}
