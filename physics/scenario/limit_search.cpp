#include "scenario/limit_search.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "scenario/parallel_runs.h"
#include "scenario/run.h"

namespace bdfcar::scenario {

namespace {

// The trials at these speeds, `jobs` at a time.
std::vector<LimitTrial> runRound(const std::vector<double>& speeds, int jobs, const LimitTrialFunction& trial) {
  std::vector<LimitTrial> out(speeds.size());
  runInParallel(static_cast<int>(speeds.size()), jobs, [&](int i) {
    out[i] = trial(speeds[i]);
    out[i].speed = speeds[i];
  });
  return out;
}

}  // namespace

LimitResult searchLimit(const LimitSearchSpec& spec, const LimitTrialFunction& trial) {
  if (!(spec.from > 0) || !(spec.to > spec.from) || !(spec.resolution > 0))
    throw std::invalid_argument("limit search: needs 0 < from < to and a positive resolution");
  const int jobs = std::max(1, spec.jobs);
  LimitResult r;
  auto record = [&](const std::vector<LimitTrial>& ts) { r.trials.insert(r.trials.end(), ts.begin(), ts.end()); };
  const std::vector<LimitTrial> ends = runRound({spec.from, spec.to}, jobs, trial);
  record(ends);
  if (!ends[0].passed) return r;
  r.anyPass = true;
  if (ends[1].passed) {
    r.allPass = true;
    r.highestPass = spec.to;
    return r;
  }
  double lo = spec.from, hi = spec.to;
  while (hi - lo > spec.resolution) {
    std::vector<double> speeds;
    for (int k = 1; k <= jobs; ++k) speeds.push_back(lo + (hi - lo) * k / (jobs + 1));
    const std::vector<LimitTrial> ts = runRound(speeds, jobs, trial);
    record(ts);
    // The lowest failing speed of the round bounds it above; the highest
    // passing speed below that, below.
    double newHi = hi;
    for (const LimitTrial& t : ts)
      if (!t.passed) newHi = std::min(newHi, t.speed);
    double newLo = lo;
    for (const LimitTrial& t : ts) {
      if (t.passed && t.speed < newHi) newLo = std::max(newLo, t.speed);
      if (t.passed && t.speed > newHi) r.nonMonotone = true;
    }
    lo = newLo;
    hi = newHi;
  }
  r.highestPass = lo;
  r.lowestFail = hi;
  return r;
}

// The scenario at entry speed v: its start and its speed hold at v, the
// hold's release (the throttle let go at the entry gate) and the duration
// scaled to the time the car takes to cover the same ground.
ScenarioSpec courseScenarioAt(const ScenarioSpec& base, double v) {
  ScenarioSpec s = base;
  const double v0 = base.speedControl.enabled ? base.speedControl.profile.target : base.initialSpeed;
  const double scale = v0 > 0 ? v0 / v : 1.0;
  s.initialSpeed = v;
  if (s.speedControl.enabled) {
    SpeedProfile& p = s.speedControl.profile;
    p.target = v;
    if (std::isfinite(p.end)) p.end *= scale;
    if (std::isfinite(p.start) && p.start > 0) p.start *= scale;
  }
  // The same ground covered (the car rolls through the settling too).
  if (scale > 1) s.duration = (base.settleTime + base.duration) * scale - base.settleTime;
  return s;
}

LimitTrial courseTrial(const ScenarioSpec& base, double v, const std::string& telemetry) {
  Simulation sim(courseScenarioAt(base, v));
  RunOptions opt;
  opt.telemetryPath = telemetry;
  opt.sample = true;
  opt.keepSamples = false;  // the judge sees every sample; nothing else needs them
  const RunResult r = runScenario(sim, opt);
  LimitTrial t;
  if (!r.ok) {
    t.verdict = "the run failed: " + r.failure;
    return t;
  }
  t.passed = r.course->passed && r.course->exitTime >= 0;
  t.verdict = courseVerdict(*r.course);
  return t;
}

std::string LimitResult::describe() const {
  char text[200];
  if (trials.empty()) return "no trial";
  const double from = trials[0].speed * 3.6, to = trials[1].speed * 3.6;
  if (!anyPass)
    std::snprintf(text, sizeof text, "no passing speed between %.1f and %.1f km/h", from, to);
  else if (allPass)
    std::snprintf(text, sizeof text, "passes at %.1f km/h, the top of the range searched (%.1f-%.1f km/h)", to, from, to);
  else
    std::snprintf(text, sizeof text, "highest passing speed %.1f km/h (fails at %.1f km/h)%s", highestPass * 3.6,
                  lowestFail * 3.6, nonMonotone ? "; a pass was seen above a fail: passing is not monotone here" : "");
  return text;
}

}  // namespace bdfcar::scenario
