// How far a run is from a reference run of the same scene (the
// work-precision measure of docs/RESULTS.md 5c), for tests that compare a
// run with its converged one.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "scenario/run.h"

namespace bdfcar::testing_run_error {

// RMS of a sampled quantity against the reference (interpolated linearly
// to the run's samples), % of the reference's peak.
template <class Of>
double rmsPercent(const scenario::RunResult& ref, const scenario::RunResult& run, Of of) {
  double sum = 0, peak = 0;
  std::size_t j = 0;
  for (const auto& s : run.samples) {
    while (j + 1 < ref.samples.size() && ref.samples[j + 1].t <= s.t) ++j;
    const auto& a = ref.samples[j];
    const auto& b = ref.samples[std::min(j + 1, ref.samples.size() - 1)];
    const double f = b.t > a.t ? std::clamp((s.t - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
    const double x = (1 - f) * of(a) + f * of(b);
    sum += (of(s) - x) * (of(s) - x);
  }
  for (const auto& s : ref.samples) peak = std::max(peak, std::abs(of(s)));
  return 100.0 * std::sqrt(sum / static_cast<double>(run.samples.size())) / peak;
}

// The work-precision measure (docs/RESULTS.md 5c): the larger RMS of yaw
// rate and lateral acceleration, % of the reference's peaks.
inline double yawAndLateralRmsPercent(const scenario::RunResult& ref, const scenario::RunResult& run) {
  return std::max(rmsPercent(ref, run, [](const vehicle::VehicleSample& s) { return s.yawRate; }),
                  rmsPercent(ref, run, [](const vehicle::VehicleSample& s) { return s.ay; }));
}

}  // namespace bdfcar::testing_run_error
