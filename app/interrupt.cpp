#include "interrupt.h"

#include <csignal>

namespace bdfcar::app {

namespace {

std::atomic<bool> gRequested{false};
std::atomic<int> gSignal{0};
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction gPrevious[3];

extern "C" void onInterrupt(int sig) {
  gSignal.store(sig);
  gRequested.store(true);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // a write interrupted by the signal goes on
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &sa, &gPrevious[i]);
}

InterruptGuard::~InterruptGuard() {
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &gPrevious[i], nullptr);
}

const std::atomic<bool>& interruptRequested() { return gRequested; }

int interruptSignal() { return gSignal.load(); }

const char* interruptSignalName() {
  switch (gSignal.load()) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
  }
  return "no signal";
}

int interruptExitStatus() { return 128 + gSignal.load(); }

}  // namespace bdfcar::app
