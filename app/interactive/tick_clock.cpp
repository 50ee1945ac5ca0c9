#include "interactive/tick_clock.h"

#include <thread>

namespace bdfcar::app {

namespace {
double seconds(TickClock::Clock::duration d) { return std::chrono::duration<double>(d).count(); }
}  // namespace

TickClock::TickClock(double tickSeconds)
    : tick_(tickSeconds),
      period_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(tickSeconds))),
      start_(Clock::now()),
      deadline_(start_),
      lastTick_(start_) {}

// Coarse sleep, then a short spin (docs/headless-gl.md 6: median 10.000 ms,
// p99 13-15 ms with sleep plus spin on a shared 2-core VM).
double TickClock::waitForTick() {
  deadline_ += period_;
  const auto spin = std::chrono::microseconds(800);
  const auto now = Clock::now();
  if (deadline_ - now > spin) std::this_thread::sleep_for(deadline_ - now - spin);
  while (Clock::now() < deadline_) {
  }
  const auto t = Clock::now();
  const double period = seconds(t - lastTick_);
  lastTick_ = t;
  return period;
}

bool TickClock::endTick() {
  const auto now = Clock::now();
  const bool overrun = now - deadline_ > period_;
  if (now - deadline_ > kMaxCatchUp * period_) deadline_ = now;
  return overrun;
}

double TickClock::sinceStart() const { return seconds(Clock::now() - start_); }

void RealTimeMeter::add(double wall, double sim) {
  wall_[head_] = wall;
  sim_[head_] = sim;
  head_ = (head_ + 1) % kSize;
  if (count_ < kSize) ++count_;
}

double RealTimeMeter::factor() const {
  // Sum back from the newest entry until a second of wall time is covered.
  double wall = 0, sim = 0;
  for (int i = 0; i < count_ && wall < 1.0; ++i) {
    const int k = (head_ - 1 - i + kSize) % kSize;
    wall += wall_[k];
    sim += sim_[k];
  }
  return wall > 0 ? sim / wall : 0.0;
}

}  // namespace bdfcar::app
