#include "session/loop_stats.h"

#include <algorithm>
#include <cstdio>
#include <sys/resource.h>

namespace bdfcar::app {

Percentiles percentiles(std::vector<double> v) {
  Percentiles p;
  if (v.empty()) return p;
  std::sort(v.begin(), v.end());
  auto at = [&](double q) { return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))]; };
  p.p50 = at(0.5);
  p.p99 = at(0.99);
  p.max = v.back();
  return p;
}

void LoopStats::tick(double period, double physicsSeconds, bool overrun) {
  if (period > 0) periods_.push_back(period);
  physics_.push_back(physicsSeconds);
  overruns_ += overrun ? 1 : 0;
}

void LoopStats::frame(double renderSeconds, double worldScale) {
  render_.push_back(renderSeconds);
  scales_.push_back(worldScale);
}

std::string LoopStats::summary() const {
  const Percentiles t = tickPeriod(), ph = physics(), r = render();
  // The share of frames whose world was drawn below full resolution, and their median scale.
  std::vector<double> reduced;
  for (double s : scales_)
    if (s < 1) reduced.push_back(s);
  // The process's peak resident set (the goal: under 250 MB while driving).
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peakMb = usage.ru_maxrss / 1024.0;  // Linux reports kilobytes
  const double fps = r.p50 > 0 ? 1 / r.p50 : 0;
  char buf[800];
  std::snprintf(buf, sizeof buf,
                "loop: %ld ticks, tick period p50 %.3f ms, p99 %.3f ms, max %.3f ms, %ld overruns\n"
                "      physics per tick p50 %.1f us, p99 %.1f us; render per frame p50 %.2f ms (%.1f fps), p99 %.2f ms (%zu frames)\n"
                "      world below full resolution in %.0f %% of the frames (median scale %.2f)\n"
                "      peak resident memory %.0f MB",
                ticks(), 1e3 * t.p50, 1e3 * t.p99, 1e3 * t.max, overruns_, 1e6 * ph.p50, 1e6 * ph.p99, 1e3 * r.p50, fps,
                1e3 * r.p99, render_.size(), scales_.empty() ? 0.0 : 100.0 * reduced.size() / scales_.size(),
                percentiles(reduced.empty() ? std::vector<double>{1.0} : reduced).p50, peakMb);
  return buf;
}

}  // namespace bdfcar::app
