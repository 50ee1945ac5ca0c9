#include "process.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

namespace bdfcar::app {

namespace {
int gArgc = 0;
char** gArgv = nullptr;
}  // namespace

void setProcessArguments(int argc, char** argv) {
  gArgc = argc;
  gArgv = argv;
}

std::string execHeadless() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "cannot locate this executable: " + ec.message();
  const std::filesystem::path headless = self.parent_path() / "bdfcar-headless";
  if (!std::filesystem::exists(headless)) return "the headless renderer '" + headless.string() + "' is not built";
  std::vector<char*> args;
  std::string name = headless.string();
  args.push_back(name.data());
  for (int i = 1; i < gArgc; ++i) args.push_back(gArgv[i]);
  args.push_back(nullptr);
  execv(name.c_str(), args.data());
  return "cannot start " + name + ": " + std::strerror(errno);
}

bool displayConfigured() {
  const char* x = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (w && *w);
}

}  // namespace bdfcar::app
