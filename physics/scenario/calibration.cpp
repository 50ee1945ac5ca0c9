#include "scenario/calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace bdfcar::scenario {

Calibration calibrate(const std::function<double(double)>& response, double target, double guess, double tolerance,
                      int maxRuns, double limit) {
  Calibration c;
  double x0 = std::clamp(guess, -limit, limit), f0 = response(x0);
  c.tries.emplace_back(x0, f0);
  auto done = [&](double x, double f) {
    if (std::abs(f - target) <= tolerance * std::abs(target)) {
      c.input = x;
      c.response = f;
      c.converged = true;
      return true;
    }
    return false;
  };
  if (done(x0, f0)) return c;
  // The second try as if the response were proportional to the input.
  double x1 = std::abs(f0) > 1e-12 ? x0 * target / f0 : 2 * x0;
  x1 = std::clamp(x1, -limit, limit);
  for (int run = 1; run < maxRuns; ++run) {
    const double f1 = response(x1);
    c.tries.emplace_back(x1, f1);
    if (done(x1, f1)) return c;
    const double slope = (f1 - f0) / (x1 - x0);
    x0 = x1;
    f0 = f1;
    if (!(std::abs(slope) > 0) || !std::isfinite(slope)) break;
    x1 = std::clamp(x1 + (target - f1) / slope, -limit, limit);
    if (x1 == x0) break;  // at the limit, and the limit is not enough
  }
  // The closest try.
  const auto best = std::min_element(c.tries.begin(), c.tries.end(), [&](const auto& a, const auto& b) {
    return std::abs(a.second - target) < std::abs(b.second - target);
  });
  c.input = best->first;
  c.response = best->second;
  return c;
}

double sisAngleAt(const TimeHistory& h, double ayTarget, double low, double high) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (size_t i = 1; i < h.t.size(); ++i) {
    const double ay = std::abs(h.ay[i]), angle = std::abs(h.steer[i]);
    if (ay < low || ay > high || !(angle > std::abs(h.steer[i - 1]))) continue;
    sx += ay;
    sy += angle;
    sxx += ay * ay;
    sxy += ay * angle;
    ++n;
  }
  if (n < 10) return std::numeric_limits<double>::quiet_NaN();
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / n;
  return intercept + slope * ayTarget;
}

std::vector<double> fmvss126Amplitudes(double A) {
  std::vector<double> out;
  if (!(A > 0)) return out;
  // The last run's amplitude: 6.5 A or 270 deg, the greater, unless some
  // step up to 6.5 A passes 300 deg: then 300 deg.
  const double last = 6.5 * A <= 300.0 ? std::max(6.5 * A, 270.0) : 300.0;
  for (double k = 1.5;; k += 0.5) {
    const double a = k * A;
    if (a >= last - 1e-9) {
      out.push_back(last);
      break;
    }
    out.push_back(a);
  }
  return out;
}

SeriesVerdict fmvss126Verdict(const std::vector<double>& amplitudes, const std::vector<SineWithDwellMetrics>& runs,
                              double A) {
  SeriesVerdict v;
  char text[200];
  for (size_t i = 0; i < runs.size() && i < amplitudes.size(); ++i) {
    const SineWithDwellMetrics& m = runs[i];
    if (!m.valid) {
      std::snprintf(text, sizeof text, "the run at %.1f deg has no metrics: %s", amplitudes[i], m.why.c_str());
    } else if (!m.passYaw1000) {
      std::snprintf(text, sizeof text, "at %.1f deg the yaw rate 1.00 s after the end of steer is %.1f %% of its peak (at most 35 %%)",
                    amplitudes[i], m.yawRatio1000);
    } else if (!m.passYaw1750) {
      std::snprintf(text, sizeof text, "at %.1f deg the yaw rate 1.75 s after the end of steer is %.1f %% of its peak (at most 20 %%)",
                    amplitudes[i], m.yawRatio1750);
    } else if (amplitudes[i] >= 5 * A - 1e-9 && !m.passDisplacement) {
      std::snprintf(text, sizeof text, "at %.1f deg (5 A or more) the lateral displacement is %.2f m (at least 1.83 m)",
                    amplitudes[i], m.lateralDisplacement);
    } else {
      continue;
    }
    v.pass = false;
    v.why = text;
    return v;
  }
  return v;
}

}  // namespace bdfcar::scenario
