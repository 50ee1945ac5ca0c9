// Each `bdfcar` sub-command registers itself on the CLI11 parser and returns
// the function that runs it once the arguments are parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace bdfcar::app {

struct Command {
  CLI::App* cli = nullptr;
  std::function<int()> run;  // process exit code
};
using CommandList = std::vector<Command>;

// `bdfcar version`: bdfcar's and its libraries' versions; displayLibraries
// are the window's and renderer's lines (SDL2, OpenSceneGraph), which only
// the executables with graphics link.
void addVersionCommand(CLI::App& app, CommandList& commands, std::vector<std::string> displayLibraries = {});
// What `bdfcar version` and `bdfcar --version` print; returns 0.
int printVersion(const std::vector<std::string>& displayLibraries = {});
void addInfoCommand(CLI::App& app, CommandList& commands);
void addKcCommand(CLI::App& app, CommandList& commands);
void addTyreCommand(CLI::App& app, CommandList& commands);
void addRunCommand(CLI::App& app, CommandList& commands);
void addLimitCommand(CLI::App& app, CommandList& commands);
void addStandardCommand(CLI::App& app, CommandList& commands);
void addSweepCommand(CLI::App& app, CommandList& commands);
void addReportCommand(CLI::App& app, CommandList& commands);
void addSoakCommand(CLI::App& app, CommandList& commands);
void addCheckCommand(CLI::App& app, CommandList& commands);
// bdfcar (on screen):
void addDriveCommand(CLI::App& app, CommandList& commands);
void addDemoCommand(CLI::App& app, CommandList& commands);
void addRenderDelegateCommand(CLI::App& app, CommandList& commands);
void addInputCommand(CLI::App& app, CommandList& commands);
// bdfcar-headless:
void addHeadlessCommands(CLI::App& app, CommandList& commands);

}  // namespace bdfcar::app
