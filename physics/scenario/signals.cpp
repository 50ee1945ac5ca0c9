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

SignalValue TableSignal::at(double t) const {
  if (t_.empty()) return {};
  if (t <= t_.front()) return {v_.front(), 0, 0};
  if (t >= t_.back()) return {v_.back(), 0, 0};
  const size_t i = static_cast<size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  const double rate = (v_[i] - v_[i - 1]) / (t_[i] - t_[i - 1]);
  return {v_[i - 1] + rate * (t - t_[i - 1]), rate, 0};
}

}  // namespace bdfcar::scenario
