// Statistics of an interactive loop: tick periods (how evenly the 10 ms
// physics ticks came), physics time per tick, render time per frame, and
// overruns (ticks later than one period past their deadline).
#pragma once

#include <string>
#include <vector>

namespace bdfcar::app {

struct Percentiles {
  double p50 = 0, p99 = 0, max = 0;
};

Percentiles percentiles(std::vector<double> values);

class LoopStats {
 public:
  void tick(double period, double physicsSeconds, bool overrun);
  // A frame's drawing time and the scale of the window's width and height its world was drawn at.
  void frame(double renderSeconds, double worldScale = 1);
  std::string summary() const;  // a few lines for the console at exit
  long ticks() const { return static_cast<long>(periods_.size()); }
  long overruns() const { return overruns_; }
  Percentiles tickPeriod() const { return percentiles(periods_); }
  Percentiles physics() const { return percentiles(physics_); }
  Percentiles render() const { return percentiles(render_); }

 private:
  std::vector<double> periods_, physics_, render_, scales_;
  long overruns_ = 0;
};

}  // namespace bdfcar::app
