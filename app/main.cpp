// bdfcar: a real-time driving simulator with a multibody vehicle in relative
// coordinates, integrated by an implicit BDF method (Park, Lee, Song, Bae).
#include <cstdio>

#include "cli_errors.h"
#include "commands.h"
#include "process.h"
#ifdef BDFCAR_WITH_GRAPHICS
#include "render/library_versions.h"
#endif

int main(int argc, char** argv) {
  using namespace bdfcar::app;
  setProcessArguments(argc, argv);
  CLI::App app{"bdfcar: real-time vehicle simulation with an implicit BDF multibody model"};
  app.require_subcommand(0, 1);
  app.fallthrough(false);
  CommandList commands;
#ifdef BDFCAR_WITH_GRAPHICS
  const std::vector<std::string> displayLibraries{bdfcar::render::sdlVersion(), bdfcar::render::osgVersion()};
#else
  const std::vector<std::string> displayLibraries;
#endif
  addVersionCommand(app, commands, displayLibraries);
  addInfoCommand(app, commands);
  addKcCommand(app, commands);
  addTyreCommand(app, commands);
  addRunCommand(app, commands);
  addLimitCommand(app, commands);
  addStandardCommand(app, commands);
  addSweepCommand(app, commands);
  addReportCommand(app, commands);
  addSoakCommand(app, commands);
  addCheckCommand(app, commands);
#ifdef BDFCAR_WITH_GRAPHICS
  addDriveCommand(app, commands);
  addDemoCommand(app, commands);
  addRenderDelegateCommand(app, commands);
  addInputCommand(app, commands);
#endif
  bool version = false;
  app.add_flag("-V,--version", version, "Print the version (as `bdfcar version`) and exit");
  requireFiniteNumbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cliExitCode(app, e);
  }
  for (const Command& c : commands)
    if (c.cli->parsed()) return c.run();
  if (version) return printVersion(displayLibraries);
  std::fprintf(stderr, "%s\nerror: name a command (see above)\n", app.help().c_str());
  return kExitUsage;
}
