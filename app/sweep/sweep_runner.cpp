#include "sweep/sweep_runner.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <optional>
#include <thread>

#include "interrupt.h"
#include "progress_bar.h"

extern char** environ;

namespace bdfcar::app {

namespace {

// Runs a command line through /bin/sh; its exit status (-1: not started or killed).
int runShell(const std::string& line) {
  const char* argv[] = {"/bin/sh", "-c", line.c_str(), nullptr};
  pid_t pid;
  if (posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

void runCommandLines(const std::vector<std::string>& lines, int jobs, bool progress) {
  std::atomic<std::size_t> next{0};
  std::optional<ProgressBar> bar;
  if (progress) bar.emplace(lines.size(), "cases");
  auto worker = [&] {
    for (std::size_t i; (i = next++) < lines.size();) {
      if (interruptRequested()) return;
      runShell(lines[i]);
      if (bar) bar->step();
    }
  };
  std::vector<std::thread> threads;
  for (int k = 0; k < jobs; ++k) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
}

}  // namespace bdfcar::app
