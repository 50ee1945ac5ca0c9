#include "scenario/run_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bdfcar::scenario {

std::vector<Metric> runMetrics(const RunResult& r) {
  double yaw = 0, ay = 0, roll = 0, sideslip = 0, speedMin = 1e300, speedMax = 0;
  double fzMin = 1e300;
  for (const vehicle::VehicleSample& s : r.samples) {
    yaw = std::max(yaw, std::abs(s.yawRate));
    ay = std::max(ay, std::abs(s.ay));
    roll = std::max(roll, std::abs(s.roll));
    // Sideslip is undefined at rest: counted above 1 m/s.
    if (s.speed > 1.0) sideslip = std::max(sideslip, std::abs(s.sideslip));
    speedMin = std::min(speedMin, s.speed);
    speedMax = std::max(speedMax, s.speed);
    for (double fz : s.Fz) fzMin = std::min(fzMin, fz);
  }
  const bool any = !r.samples.empty();
  std::vector<Metric> m = {
      {"ok", r.ok ? 1.0 : 0.0},
      {"duration_s", any ? r.samples.back().t : 0.0},
      {"peak_yaw_rate_radps", yaw},
      {"peak_ay_mps2", ay},
      {"peak_roll_deg", roll * 180 / M_PI},
      {"peak_sideslip_deg", sideslip * 180 / M_PI},
      {"min_speed_mps", any ? speedMin : 0.0},
      {"max_speed_mps", speedMax},
      {"final_speed_mps", any ? r.samples.back().speed : 0.0},
      {"min_tyre_load_N", any ? fzMin : 0.0},
  };
  if (r.course) {
    m.push_back({"course_passed", r.course->passed && r.course->exitTime >= 0 ? 1.0 : 0.0});
    m.push_back({"cones_hit", static_cast<double>(r.course->coneHits)});
    // Speeds at the course's entry and exit (0 when not reached).
    auto speedAt = [&](double t) {
      for (const vehicle::VehicleSample& s : r.samples)
        if (t >= 0 && s.t >= t) return s.speed;
      return 0.0;
    };
    m.push_back({"course_entry_speed_mps", speedAt(r.course->entryTime)});
    m.push_back({"course_exit_speed_mps", speedAt(r.course->exitTime)});
    m.push_back({"course_peak_ay_mps2", r.course->peakLateralAcceleration});
  }
  return m;
}

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}
}  // namespace

std::string metricsCsv(const std::vector<Metric>& m) {
  std::string head, row;
  for (const Metric& x : m) {
    if (!head.empty()) head += ',', row += ',';
    head += x.name;
    row += number(x.value);
  }
  return head + "\n" + row + "\n";
}

std::string metricsJson(const std::vector<Metric>& m) {
  std::string out = "{";
  for (const Metric& x : m) {
    if (out.size() > 1) out += ", ";
    out += '"';
    out += x.name;
    out += "\": ";
    // JSON has no NaN or inf: a metric that is not a number is null.
    out += std::isfinite(x.value) ? number(x.value) : std::string("null");
  }
  out += "}\n";
  return out;
}

}  // namespace bdfcar::scenario
