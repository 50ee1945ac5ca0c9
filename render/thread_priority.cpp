#include "render/thread_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>

namespace bdfcar::render {
namespace {

// On Linux, PRIO_PROCESS with a thread id addresses that thread alone.
void lowerPriorityOf(id_t tid) {
  errno = 0;
  const int current = getpriority(PRIO_PROCESS, tid);
  if (errno != 0) return;
  setpriority(PRIO_PROCESS, tid, current + kBackgroundNiceness > 19 ? 19 : current + kBackgroundNiceness);
}

}  // namespace

void lowerThisThreadsPriority() { lowerPriorityOf(static_cast<id_t>(syscall(SYS_gettid))); }

int lowerSoftwareRasteriserPriority() {
  int found = 0;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    std::ifstream comm(task.path() / "comm");
    std::string name;
    if (!std::getline(comm, name) || name.rfind("llvmpipe-", 0) != 0) continue;
    try {
      lowerPriorityOf(static_cast<id_t>(std::stoul(task.path().filename().string())));
      ++found;
    } catch (const std::exception&) {
      // Not a thread id: nothing to lower.
    }
  }
  return found;
}

}  // namespace bdfcar::render
