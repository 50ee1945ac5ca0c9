// SIGINT, SIGTERM and SIGHUP end a run cleanly instead of killing it: the
// handler only sets a flag, the run loops look at it after each tick, close
// their outputs (the telemetry ends on a complete row) and print their
// summary; the command then exits with 128 + the signal's number, as a shell
// expects of a program stopped by that signal.
#pragma once

#include <atomic>

namespace bdfcar::app {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // restores the previous ones
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// Set once one of the signals arrived.
const std::atomic<bool>& interruptRequested();
// The signal's number (0 if none) and its name ("SIGINT", ...).
int interruptSignal();
const char* interruptSignalName();
// The exit status of an interrupted command: 128 + the signal's number.
int interruptExitStatus();

}  // namespace bdfcar::app
