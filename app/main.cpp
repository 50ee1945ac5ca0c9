// bdfcar: a real-time driving simulator with a multibody vehicle in relative
// coordinates, integrated by an implicit BDF method (Park, Lee, Song, Bae).
#include <cstdio>

#include "commands.h"

int main(int argc, char** argv) {
  using namespace bdfcar::app;
  CLI::App app{"bdfcar: real-time vehicle simulation with an implicit BDF multibody model"};
  app.require_subcommand(1);
  app.fallthrough(false);
  CommandList commands;
  addVersionCommand(app, commands);
  addInfoCommand(app, commands);
  addRunCommand(app, commands);
  CLI11_PARSE(app, argc, argv);
  for (const Command& c : commands)
    if (c.cli->parsed()) return c.run();
  return 2;
}
