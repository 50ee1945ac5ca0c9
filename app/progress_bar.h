// A progress bar on stderr for work done in parallel: "[#####     ] 12/34
// runs", redrawn in place on a terminal, a line per step otherwise (a log).
#pragma once

#include <cstddef>
#include <mutex>
#include <string>

namespace bdfcar::app {

class ProgressBar {
 public:
  ProgressBar(std::size_t total, std::string unit);
  ~ProgressBar();  // ends the line on a terminal
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  void step();  // one more done; any thread

 private:
  std::size_t total_, done_ = 0;
  std::string unit_;
  bool tty_;
  std::mutex mutex_;
};

}  // namespace bdfcar::app
