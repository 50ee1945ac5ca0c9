#include "progress_bar.h"

#include <cstdio>
#include <unistd.h>

namespace bdfcar::app {

ProgressBar::ProgressBar(std::size_t total, std::string unit)
    : total_(total), unit_(std::move(unit)), tty_(isatty(STDERR_FILENO)) {}

ProgressBar::~ProgressBar() {
  if (tty_ && done_ > 0) std::fprintf(stderr, "\n");
}

void ProgressBar::step() {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  const int width = 30, filled = total_ ? static_cast<int>(width * done_ / total_) : width;
  std::fprintf(stderr, "%s[%.*s%*s] %zu/%zu %s%s", tty_ ? "\r" : "", filled, "##############################",
               width - filled, "", done_, total_, unit_.c_str(), tty_ ? "" : "\n");
  std::fflush(stderr);
}

}  // namespace bdfcar::app
