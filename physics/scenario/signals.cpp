#include "scenario/signals.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bdfcar::scenario {

SignalValue RampSignal::at(double t) const {
  if (t < start_) return {};
  if (t < start_ + rise_) return {level_ * (t - start_) / rise_, level_ / rise_, 0};
  return {level_, 0, 0};
}

SignalValue SinePeriodSignal::at(double t) const {
  if (t < start_ || t >= start_ + period_) return {};
  const double w = 2 * std::numbers::pi / period_, x = w * (t - start_);
  return {amplitude_ * std::sin(x), amplitude_ * w * std::cos(x), -amplitude_ * w * w * std::sin(x)};
}

SignalValue SquareSignal::at(double t) const {
  if (!(t >= start_)) return {};
  const double phase = std::fmod(t - start_, period_) / period_;
  return {phase < 0.5 ? amplitude_ : -amplitude_, 0, 0};
}

// Linear between the samples, held before the first and after the last. The
// loader guarantees finite, strictly increasing times; the comparisons are
// written so that a NaN (t or a time) still lands on a sample, never past the end.
SignalValue TableSignal::at(double t) const {
  if (t_.empty() || v_.size() != t_.size()) return {};
  if (!(t > t_.front())) return {v_.front(), 0, 0};
  if (!(t < t_.back())) return {v_.back(), 0, 0};
  const size_t n = t_.size();
  const size_t i = std::clamp<size_t>(static_cast<size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()), 1, n - 1);
  const double rate = (v_[i] - v_[i - 1]) / (t_[i] - t_[i - 1]);
  return {v_[i - 1] + rate * (t - t_[i - 1]), rate, 0};
}

SignalValue RampedInSignal::at(double t) const {
  if (t >= 0 || t0_ >= 0) return inner_->at(t);
  if (t <= t0_) return {0, 0, 0};
  const double v0 = inner_->at(0.0).value, span = -t0_;
  const double u = (t - t0_) / span;
  return {v0 * u * u * (3 - 2 * u), v0 * 6 * u * (1 - u) / span, v0 * (6 - 12 * u) / (span * span)};
}

}  // namespace bdfcar::scenario
