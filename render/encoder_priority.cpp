#include "render/encoder_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>

namespace bdfcar::render {

void lowerThisThreadsPriority() {
  // On Linux, PRIO_PROCESS with a thread id addresses that thread alone.
  const auto tid = static_cast<id_t>(syscall(SYS_gettid));
  errno = 0;
  const int current = getpriority(PRIO_PROCESS, tid);
  if (errno != 0) return;
  setpriority(PRIO_PROCESS, tid, current + kEncoderNiceness > 19 ? 19 : current + kEncoderNiceness);
}

}  // namespace bdfcar::render
