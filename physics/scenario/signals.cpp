#include "scenario/signals.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include "portable_math.h"

namespace bdfcar::scenario {

SignalValue RampSignal::at(double t) const {
  if (t < start_) return {};
  if (t < start_ + rise_) return {level_ * (t - start_) / rise_, level_ / rise_, 0};
  return {level_, 0, 0};
}

namespace {
// amplitude sin(w tau) and its two derivatives.
SignalValue sine(double amplitude, double w, double tau) {
  const double x = w * tau;
  return {amplitude * pm::sin(x), amplitude * w * pm::cos(x), -amplitude * w * w * pm::sin(x)};
}
}  // namespace

SignalValue SinePeriodSignal::at(double t) const {
  if (!(t >= start_) || t >= start_ + periods_ * period_) return {};
  return sine(amplitude_, 2 * std::numbers::pi / period_, t - start_);
}

SignalValue SineWithDwellSignal::at(double t) const {
  const double w = 2 * std::numbers::pi / period_, tau = t - start_;
  if (!(tau >= 0)) return {};
  if (tau < 0.75 * period_) return sine(amplitude_, w, tau);
  if (tau < 0.75 * period_ + dwell_) return {-amplitude_, 0, 0};
  if (tau < period_ + dwell_) return sine(amplitude_, w, tau - dwell_);
  return {};
}

SignalValue ChirpSignal::at(double t) const {
  const double tau = t - start_;
  if (!(tau >= 0) || tau >= duration_) return {};
  const double k = (f1_ - f0_) / duration_, two_pi = 2 * std::numbers::pi;
  const double phi = two_pi * (f0_ * tau + 0.5 * k * tau * tau), rate = two_pi * (f0_ + k * tau), accel = two_pi * k;
  const double s = pm::sin(phi), c = pm::cos(phi);
  return {amplitude_ * s, amplitude_ * c * rate, amplitude_ * (c * accel - s * rate * rate)};
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
