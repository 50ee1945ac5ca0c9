#include <Eigen/Core>
#include <cstdio>

#include "commands.h"

namespace bdfcar::app {

int printVersion() {
  std::printf("bdfcar %s\n", BDFCAR_VERSION);
  std::printf("  Eigen %d.%d.%d\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  std::printf("  compiler %s\n", __VERSION__);
  return 0;
}

void addVersionCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand("version", "Print the version of bdfcar and of the libraries it was built with");
  commands.push_back({cmd, [] { return printVersion(); }});
}

}  // namespace bdfcar::app
