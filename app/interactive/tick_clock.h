// The driver's tick on the wall clock: absolute deadlines (a coarse sleep,
// then a short spin) one tick apart, with capped catch-up: far behind (a
// stall), the clock restarts from now instead of racing through the backlog.
#pragma once

#include <chrono>

namespace bdfcar::app {

class TickClock {
 public:
  using Clock = std::chrono::steady_clock;
  explicit TickClock(double tickSeconds);
  // Waits for the next deadline; returns the wall time since the last tick began (s).
  double waitForTick();
  // After the tick's work: true when it ended more than one tick past its
  // deadline (an overrun). Restarts the deadlines after a stall.
  bool endTick();
  double tick() const { return tick_; }
  double sinceStart() const;      // s of wall time since the clock was made
  Clock::time_point tickStart() const { return lastTick_; }

  static constexpr int kMaxCatchUp = 5;  // ticks run back to back at most before the clock restarts

 private:
  double tick_;
  Clock::duration period_;
  Clock::time_point start_, deadline_, lastTick_;
};

// The real-time factor averaged over the last second of wall time: simulated
// time advanced over wall time elapsed (it reads 1 when the simulation keeps
// up with the clock, whatever the integration step).
class RealTimeMeter {
 public:
  void add(double wallSeconds, double simSeconds);
  double factor() const;

 private:
  static constexpr int kSize = 1024;  // a second of ticks down to the 1 ms minimum
  double wall_[kSize]{}, sim_[kSize]{};
  int head_ = 0, count_ = 0;
};

}  // namespace bdfcar::app
