#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <cstdio>
#include <spdlog/version.h>

#include "commands.h"
#include "terrain/bullet/bullet_terrain.h"

namespace bdfcar::app {

int printVersion(const std::vector<std::string>& displayLibraries) {
  std::printf("bdfcar %s\n", BDFCAR_VERSION);
  std::printf("  Eigen %d.%d.%d\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  std::printf("  Bullet %s (terrain ray queries)\n", terrain::bulletVersion().c_str());
  std::printf("  CLI11 %s, spdlog %d.%d.%d\n", CLI11_VERSION, SPDLOG_VER_MAJOR, SPDLOG_VER_MINOR, SPDLOG_VER_PATCH);
  for (const std::string& line : displayLibraries) std::printf("  %s\n", line.c_str());
  std::printf("  compiler %s\n", __VERSION__);
  return 0;
}

void addVersionCommand(CLI::App& app, CommandList& commands, std::vector<std::string> displayLibraries) {
  CLI::App* cmd = app.add_subcommand("version", "Print the version of bdfcar and of the libraries it was built with");
  commands.push_back({cmd, [displayLibraries] { return printVersion(displayLibraries); }});
}

}  // namespace bdfcar::app
