// bdfcar-headless: rendering without a display server (OSMesa). libOSMesa is
// the first NEEDED library of this executable (checked at link time), so the
// gl* calls of OpenSceneGraph reach OSMesa, not glvnd.
#include <cstdio>

#include "commands.h"
#include "process.h"

int main(int argc, char** argv) {
  using namespace bdfcar::app;
  setProcessArguments(argc, argv);
  CLI::App app{"bdfcar-headless: render bdfcar scenarios to frames and video without a display"};
  app.require_subcommand(0, 1);
  CommandList commands;
  addVersionCommand(app, commands);
  addHeadlessCommands(app, commands);
  CLI11_PARSE(app, argc, argv);
  for (const Command& c : commands)
    if (c.cli->parsed()) return c.run();
  std::fprintf(stderr, "%s\nerror: name a command (see above)\n", app.help().c_str());
  return 2;
}
