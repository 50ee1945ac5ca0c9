#include "scenario/standard_tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "vehicle/motion_ratio.h"
#include "portable_math.h"

namespace bdfcar::scenario {

namespace {

// Linear interpolation of y at time tq (clamped to the ends).
double at(const std::vector<double>& t, const std::vector<double>& y, double tq) {
  if (tq <= t.front()) return y.front();
  if (tq >= t.back()) return y.back();
  const size_t i = static_cast<size_t>(std::upper_bound(t.begin(), t.end(), tq) - t.begin());
  const double w = (tq - t[i - 1]) / (t[i] - t[i - 1]);
  return y[i - 1] + w * (y[i] - y[i - 1]);
}

// First time at or after index `from` where f(i) - level changes sign
// upwards (f rises through level), interpolated; -1 if never.
template <class F>
double firstRise(const std::vector<double>& t, size_t from, double level, F f) {
  for (size_t i = std::max<size_t>(from, 1); i < t.size(); ++i) {
    const double a = f(i - 1) - level, b = f(i) - level;
    if (a < 0 && b >= 0) return t[i - 1] + (t[i] - t[i - 1]) * (-a / (b - a));
    if (i == std::max<size_t>(from, 1) && a >= 0) return t[i - 1];
  }
  return -1;
}

size_t indexAt(const std::vector<double>& t, double tq) {
  return static_cast<size_t>(std::lower_bound(t.begin(), t.end(), tq) - t.begin());
}

bool sizesMatch(const TimeHistory& h, const std::vector<double>& v) { return v.size() == h.t.size(); }

StepResponse stepResponse(const TimeHistory& h, const std::vector<double>& y, size_t window, double step, double t50) {
  StepResponse r;
  const double y0 = y.front();
  double sum = 0;
  for (size_t i = window; i < y.size(); ++i) sum += y[i] - y0;
  r.steady = sum / static_cast<double>(y.size() - window);
  r.gain = r.steady / step;
  const double sign = r.steady >= 0 ? 1.0 : -1.0;
  const size_t from = indexAt(h.t, t50);
  auto rel = [&](size_t i) { return sign * (y[i] - y0); };
  const double t90 = firstRise(h.t, from, 0.9 * std::abs(r.steady), rel);
  r.responseTime = t90 < 0 ? NAN : t90 - t50;
  size_t peak = from;
  for (size_t i = from; i < y.size(); ++i)
    if (rel(i) > rel(peak)) peak = i;
  r.peakTime = h.t[peak] - t50;
  r.overshoot = std::max(0.0, (rel(peak) - std::abs(r.steady)) / std::abs(r.steady));
  return r;
}

}  // namespace

StepSteerMetrics iso7401StepSteer(const TimeHistory& h, double steadyWindow) {
  StepSteerMetrics m;
  if (h.t.size() < 3 || !sizesMatch(h, h.steer) || !sizesMatch(h, h.yawRate) || !sizesMatch(h, h.ay)) {
    m.why = "too few samples, or channels of different lengths";
    return m;
  }
  const size_t window = indexAt(h.t, h.t.back() - steadyWindow);
  if (window == 0 || window >= h.t.size() - 1) {
    m.why = "the run is shorter than its steady window";
    return m;
  }
  double sum = 0;
  for (size_t i = window; i < h.t.size(); ++i) sum += h.steer[i] - h.steer.front();
  const double step = sum / static_cast<double>(h.t.size() - window);
  if (!(std::abs(step) > 0)) {
    m.why = "no steering step";
    return m;
  }
  const double sign = step > 0 ? 1.0 : -1.0;
  m.steerStep = step;
  m.t50 = firstRise(h.t, 0, 0.5 * std::abs(step), [&](size_t i) { return sign * (h.steer[i] - h.steer.front()); });
  if (m.t50 < 0) {
    m.why = "the steering never reaches half its step";
    return m;
  }
  m.yawRate = stepResponse(h, h.yawRate, window, step, m.t50);
  m.ay = stepResponse(h, h.ay, window, step, m.t50);
  m.valid = std::abs(m.yawRate.steady) > 0 && std::abs(m.ay.steady) > 0;
  if (!m.valid) m.why = "no steady response";
  return m;
}

SineWithDwellMetrics fmvss126SineWithDwell(const TimeHistory& h, double beginThreshold) {
  SineWithDwellMetrics m;
  const size_t n = h.t.size();
  if (n < 3 || !sizesMatch(h, h.steer) || !sizesMatch(h, h.yawRate) || !sizesMatch(h, h.x) ||
      !sizesMatch(h, h.y) || !sizesMatch(h, h.heading)) {
    m.why = "too few samples, or channels of different lengths";
    return m;
  }
  // Beginning of steer: |steer| first reaches the threshold; its sign is the first lobe's.
  size_t b = 0;
  while (b < n && std::abs(h.steer[b]) < beginThreshold) ++b;
  if (b == n || b == 0) {
    m.why = "the steering never reaches the beginning-of-steer threshold";
    return m;
  }
  const double s1 = h.steer[b] > 0 ? 1.0 : -1.0;
  m.beginOfSteer = firstRise(h.t, b - 1, beginThreshold, [&](size_t i) { return s1 * h.steer[i]; });
  // The reversal (the steering crosses zero into the second lobe), then the
  // completion of steer: the second lobe back to zero.
  // The second lobe is done when it is back within kZeroBand of its own
  // peak from zero (a steering system approaches zero, it need not cross it).
  size_t r = b;
  while (r < n && s1 * h.steer[r] > 0) ++r;
  double lobe = 0;
  size_t c = r;
  while (c < n && -s1 * h.steer[c] > SineWithDwellMetrics::kZeroBand * lobe) lobe = std::max(lobe, -s1 * h.steer[c++]);
  if (r >= n || c >= n || c == r || !(lobe > 0)) {
    m.why = "the steering does not complete a second lobe";
    return m;
  }
  const double band = SineWithDwellMetrics::kZeroBand * lobe;
  const double a = -s1 * h.steer[c - 1] - band, bb = -s1 * h.steer[c] - band;
  m.completionOfSteer = h.t[c - 1] + (h.t[c] - h.t[c - 1]) * (a / (a - bb));
  if (m.completionOfSteer + 1.75 > h.t.back() || m.beginOfSteer + 1.07 > h.t.back()) {
    m.why = "the run ends less than 1.75 s after the completion of steer";
    return m;
  }
  // The peak yaw rate the second lobe produces: the largest in its direction
  // from the reversal to 1 s after the completion of steer.
  const size_t peakEnd = indexAt(h.t, m.completionOfSteer + 1.0);
  for (size_t i = r; i < peakEnd; ++i) m.peakYawRate = std::max(m.peakYawRate, -s1 * h.yawRate[i]);
  if (!(m.peakYawRate > 0)) {
    m.why = "no yaw rate in the direction of the second steering lobe";
    return m;
  }
  m.yawRatio1000 = 100.0 * -s1 * at(h.t, h.yawRate, m.completionOfSteer + 1.0) / m.peakYawRate;
  m.yawRatio1750 = 100.0 * -s1 * at(h.t, h.yawRate, m.completionOfSteer + 1.75) / m.peakYawRate;
  // Lateral displacement of the centre of mass from its path at the
  // beginning of steer, in the direction of the first lobe.
  const double t0 = m.beginOfSteer, t1 = t0 + 1.07;
  const double h0 = at(h.t, h.heading, t0);
  const double dx = at(h.t, h.x, t1) - at(h.t, h.x, t0), dy = at(h.t, h.y, t1) - at(h.t, h.y, t0);
  m.lateralDisplacement = s1 * (-pm::sin(h0) * dx + pm::cos(h0) * dy);
  m.passYaw1000 = m.yawRatio1000 <= SineWithDwellMetrics::kYaw1000Limit;
  m.passYaw1750 = m.yawRatio1750 <= SineWithDwellMetrics::kYaw1750Limit;
  m.passDisplacement = m.lateralDisplacement >= SineWithDwellMetrics::kDisplacementLimit;
  m.valid = true;
  return m;
}

TimeHistory timeHistory(const RunResult& r, double steeringWheelFull, double wheelbase) {
  TimeHistory h;
  h.wheelbase = wheelbase;
  const double wheelDeg = steeringWheelFull * 180.0 / 3.14159265358979323846;
  for (size_t i = 0; i < r.samples.size() && i < r.steerInputs.size(); ++i) {
    const vehicle::VehicleSample& s = r.samples[i];
    h.t.push_back(s.t);
    h.steer.push_back(wheelDeg * r.steerInputs[i]);
    h.yawRate.push_back(s.yawRate);
    h.ay.push_back(s.ay);
    h.x.push_back(s.com.x());
    h.y.push_back(s.com.y());
    h.heading.push_back(s.yaw);
    h.speed.push_back(s.speed);
    h.sideslip.push_back(s.sideslip);
    h.roll.push_back(s.roll);
  }
  return h;
}

TimeHistory timeHistory(const RunResult& r, const vehicle::Vehicle& v) {
  const auto& c = v.layout.wheelCentreAtDesign;
  const double wheelbase = 0.5 * (c[0].x() + c[1].x()) - 0.5 * (c[2].x() + c[3].x());
  TimeHistory h = timeHistory(r, v.spec.steering.steeringWheelFull, wheelbase);
  const double perSteer = vehicle::roadWheelAnglePerSteer(v);  // 0 where the model does not assemble
  if (perSteer > 0) h.steeringRatio = v.spec.steering.steeringWheelFull / perSteer;
  return h;
}

namespace {
// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  return sxy / sxx;
}
}  // namespace

SteadyStateMetrics iso4138ConstantSteer(const TimeHistory& h, double ayLow, double ayHigh) {
  SteadyStateMetrics m;
  m.ayLow = ayLow;
  m.ayHigh = ayHigh;
  if (!(h.wheelbase > 0)) {
    m.why = "no wheelbase";
    return m;
  }
  std::vector<double> ay, curvature, beta, roll;
  double steerSum = 0;
  for (size_t i = 0; i < h.t.size(); ++i) {
    const double a = std::abs(h.ay[i]);
    m.maxAy = std::max(m.maxAy, a);
    if (a < ayLow || a > ayHigh || h.speed[i] < 1.0) continue;
    // Left and right turns alike: signs taken with the turn's.
    const double turn = h.ay[i] > 0 ? 1.0 : -1.0;
    ay.push_back(a);
    // delta - L / R (delta: 0 when no steering ratio is known, the steer being held).
    const double delta = h.steeringRatio > 0 ? h.steer[i] / h.steeringRatio * 3.14159265358979323846 / 180.0 : 0.0;
    curvature.push_back(turn * (h.wheelbase * h.yawRate[i] / h.speed[i] - delta));
    beta.push_back(turn * h.sideslip[i]);
    roll.push_back(turn * h.roll[i]);
    steerSum += h.steer[i];
  }
  m.samples = static_cast<int>(ay.size());
  if (m.samples < 10) {
    m.why = "fewer than 10 samples with |a_y| in [" + std::to_string(ayLow) + ", " + std::to_string(ayHigh) + "] m/s^2";
    return m;
  }
  const double deg = 180.0 / 3.14159265358979323846;
  m.steer = steerSum / m.samples;
  m.understeerGradient = -slope(ay, curvature) * deg * 9.81;
  m.sideslipGradient = slope(ay, beta) * deg;
  m.rollGradient = slope(ay, roll) * deg;
  m.valid = true;
  return m;
}

std::string describe(const SteadyStateMetrics& m) {
  if (!m.valid) return "ISO 4138 " + m.method + ": no metrics (" + m.why + ")\n";
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "ISO 4138 %s (steering wheel at %.1f deg on average; %d samples with a_y in [%.1f, %.1f] m/s^2, "
                "largest a_y %.2f m/s^2):\n"
                "  understeer gradient %.3f deg/g, sideslip gradient %.4f deg/(m/s^2), roll gradient %.4f "
                "deg/(m/s^2)\n",
                m.method.c_str(), m.steer, m.samples, m.ayLow, m.ayHigh, m.maxAy, m.understeerGradient, m.sideslipGradient,
                m.rollGradient);
  return buf;
}

std::string toJson(const SteadyStateMetrics& m) {
  if (!m.valid) return "{\"test\": \"iso4138_constant_steer\", \"valid\": false, \"why\": \"" + m.why + "\"}\n";
  char buf[500];
  std::snprintf(buf, sizeof buf,
                "{\"test\": \"iso4138_constant_steer\", \"valid\": true, \"steer_deg\": %.6g, \"understeer_gradient_deg_per_g\": "
                "%.6g, \"sideslip_gradient_deg_per_mps2\": %.6g, \"roll_gradient_deg_per_mps2\": %.6g, \"ay_window_mps2\": "
                "[%.6g, %.6g], \"samples\": %d, \"max_ay_mps2\": %.6g}\n",
                m.steer, m.understeerGradient, m.sideslipGradient, m.rollGradient, m.ayLow, m.ayHigh, m.samples, m.maxAy);
  return buf;
}

StandardTestReport standardTestReport(StandardTest test, const TimeHistory& h) {
  StandardTestReport r;
  if (test == StandardTest::Iso7401StepSteer) {
    const StepSteerMetrics m = iso7401StepSteer(h);
    r = {m.valid, describe(m), toJson(m), {{"iso7401_valid", m.valid ? 1.0 : 0.0}}};
    if (m.valid) {
      r.metrics.push_back({"iso7401_steer_step_deg", m.steerStep});
      r.metrics.push_back({"iso7401_t50_s", m.t50});
      for (const auto& [name, x] : {std::pair{"yaw_rate", &m.yawRate}, std::pair{"ay", &m.ay}}) {
        const std::string p = std::string("iso7401_") + name;
        r.metrics.push_back({p + "_steady", x->steady});
        r.metrics.push_back({p + "_gain", x->gain});
        r.metrics.push_back({p + "_response_time_s", x->responseTime});
        r.metrics.push_back({p + "_peak_response_time_s", x->peakTime});
        r.metrics.push_back({p + "_overshoot", x->overshoot});
      }
    }
  } else if (test == StandardTest::Iso4138ConstantSteer || test == StandardTest::Iso4138ConstantRadius) {
    SteadyStateMetrics m = iso4138ConstantSteer(h);
    m.method = test == StandardTest::Iso4138ConstantRadius ? "constant radius" : "constant steering-wheel angle";
    r = {m.valid, describe(m), toJson(m), {{"iso4138_valid", m.valid ? 1.0 : 0.0}}};
    if (m.valid)
      r.metrics.insert(r.metrics.end(), {{"iso4138_understeer_gradient_deg_per_g", m.understeerGradient},
                                         {"iso4138_sideslip_gradient_deg_per_mps2", m.sideslipGradient},
                                         {"iso4138_roll_gradient_deg_per_mps2", m.rollGradient},
                                         {"iso4138_max_ay_mps2", m.maxAy}});
  } else if (test == StandardTest::Fmvss126SineWithDwell) {
    const SineWithDwellMetrics m = fmvss126SineWithDwell(h);
    r = {m.valid, describe(m), toJson(m), {{"fmvss126_valid", m.valid ? 1.0 : 0.0}}};
    if (m.valid)
      r.metrics.insert(r.metrics.end(), {{"fmvss126_begin_of_steer_s", m.beginOfSteer},
                                         {"fmvss126_completion_of_steer_s", m.completionOfSteer},
                                         {"fmvss126_peak_yaw_rate_radps", m.peakYawRate},
                                         {"fmvss126_yaw_ratio_1000_pct", m.yawRatio1000},
                                         {"fmvss126_yaw_ratio_1750_pct", m.yawRatio1750},
                                         {"fmvss126_lateral_displacement_m", m.lateralDisplacement},
                                         {"fmvss126_pass", m.passYaw1000 && m.passYaw1750 && m.passDisplacement ? 1.0 : 0.0}});
  }
  return r;
}

std::string describe(const StepSteerMetrics& m) {
  if (!m.valid) return "ISO 7401 step steer: no metrics (" + m.why + ")\n";
  char buf[900];
  std::snprintf(buf, sizeof buf,
                "ISO 7401 step steer (steering-wheel step %.4g deg, at 50 %% at t50 = %.3f s):\n"
                "  yaw rate: steady %.4f rad/s (gain %.4g per deg of steering wheel), response time %.3f s, "
                "peak response time %.3f s, overshoot %.1f %%\n"
                "  lateral acceleration: steady %.3f m/s^2 (gain %.4g), response time %.3f s, peak response time "
                "%.3f s, overshoot %.1f %%\n",
                m.steerStep, m.t50, m.yawRate.steady, m.yawRate.gain, m.yawRate.responseTime, m.yawRate.peakTime,
                100 * m.yawRate.overshoot, m.ay.steady, m.ay.gain, m.ay.responseTime, m.ay.peakTime,
                100 * m.ay.overshoot);
  return buf;
}

std::string describe(const SineWithDwellMetrics& m) {
  if (!m.valid) return "FMVSS 126 sine with dwell: no metrics (" + m.why + ")\n";
  char buf[900];
  auto verdict = [](bool ok) { return ok ? "pass" : "FAIL"; };
  std::snprintf(buf, sizeof buf,
                "FMVSS 126 sine with dwell (BOS %.3f s, COS %.3f s, peak yaw rate %.4f rad/s):\n"
                "  yaw rate 1.00 s after COS: %.1f %% of peak (limit %.0f %%): %s\n"
                "  yaw rate 1.75 s after COS: %.1f %% of peak (limit %.0f %%): %s\n"
                "  lateral displacement 1.07 s after BOS: %.2f m (at least %.2f m): %s\n",
                m.beginOfSteer, m.completionOfSteer, m.peakYawRate, m.yawRatio1000,
                SineWithDwellMetrics::kYaw1000Limit, verdict(m.passYaw1000), m.yawRatio1750,
                SineWithDwellMetrics::kYaw1750Limit, verdict(m.passYaw1750), m.lateralDisplacement,
                SineWithDwellMetrics::kDisplacementLimit, verdict(m.passDisplacement));
  return buf;
}

namespace {
std::string json(const char* name, const StepResponse& r) {
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "\"%s\": {\"steady\": %.6g, \"gain\": %.6g, \"response_time_s\": %.6g, \"peak_response_time_s\": "
                "%.6g, \"overshoot\": %.6g}",
                name, r.steady, r.gain, r.responseTime, r.peakTime, r.overshoot);
  return buf;
}
}  // namespace

std::string toJson(const StepSteerMetrics& m) {
  if (!m.valid) return "{\"test\": \"iso7401_step_steer\", \"valid\": false, \"why\": \"" + m.why + "\"}\n";
  char head[200];
  std::snprintf(head, sizeof head, "{\"test\": \"iso7401_step_steer\", \"valid\": true, \"steer_step\": %.6g, \"t50_s\": %.6g, ",
                m.steerStep, m.t50);
  return head + json("yaw_rate_radps", m.yawRate) + ", " + json("ay_mps2", m.ay) + "}\n";
}

std::string toJson(const SineWithDwellMetrics& m) {
  if (!m.valid) return "{\"test\": \"fmvss126_sine_with_dwell\", \"valid\": false, \"why\": \"" + m.why + "\"}\n";
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "{\"test\": \"fmvss126_sine_with_dwell\", \"valid\": true, \"bos_s\": %.6g, \"cos_s\": %.6g, "
                "\"peak_yaw_rate_radps\": %.6g, \"yaw_ratio_1000_pct\": %.6g, \"yaw_ratio_1750_pct\": %.6g, "
                "\"lateral_displacement_m\": %.6g, \"pass_yaw_1000\": %s, \"pass_yaw_1750\": %s, "
                "\"pass_displacement\": %s}\n",
                m.beginOfSteer, m.completionOfSteer, m.peakYawRate, m.yawRatio1000, m.yawRatio1750,
                m.lateralDisplacement, m.passYaw1000 ? "true" : "false", m.passYaw1750 ? "true" : "false",
                m.passDisplacement ? "true" : "false");
  return buf;
}

}  // namespace bdfcar::scenario
