// Scripted input signals (scenario/signals.h): their shapes at known points
// and their first and second derivatives against central differences of
// their own values (the rack driver uses them at the velocity and
// acceleration constraint levels, so a wrong derivative is a wrong motion).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scenario/signals.h"

namespace bdfcar::scenario {
namespace {

void expectDerivatives(const Signal& s, double t) {
  const double e = 1e-6;
  const SignalValue v = s.at(t), p = s.at(t + e), m = s.at(t - e);
  EXPECT_NEAR(v.rate, (p.value - m.value) / (2 * e), 1e-5 * (1 + std::abs(v.rate))) << "t = " << t;
  EXPECT_NEAR(v.accel, (p.rate - m.rate) / (2 * e), 1e-3 * (1 + std::abs(v.accel))) << "t = " << t;
}

TEST(Signals, SineOfSeveralPeriods) {
  const SinePeriodSignal s(1.0, 0.5, 0.3, 3);
  EXPECT_NEAR(s.at(1.0 + 0.3).value, 0.3 * std::sin(2 * std::numbers::pi * 0.3 / 0.5), 1e-12);
  EXPECT_NEAR(s.at(1.0 + 0.5 * 2 + 0.125).value, 0.3, 1e-12);  // a peak in the third period
  EXPECT_EQ(s.at(1.0 + 1.5 + 1e-9).value, 0.0);                // after three periods
  EXPECT_EQ(s.at(0.99).value, 0.0);
  for (double t : {1.1, 1.37, 2.2}) expectDerivatives(s, t);
}

TEST(Signals, SineWithDwellHasItsShapeAndIsSmoothAcrossItsDwell) {
  const double start = 1.0, period = 1.0 / 0.7, amplitude = 0.8, dwell = 0.5;
  const SineWithDwellSignal s(start, period, amplitude, dwell);
  EXPECT_NEAR(s.at(start + 0.25 * period).value, amplitude, 1e-12);
  EXPECT_NEAR(s.at(start + 0.75 * period).value, -amplitude, 1e-12);
  EXPECT_NEAR(s.at(start + 0.75 * period + 0.5 * dwell).value, -amplitude, 1e-12);
  EXPECT_NEAR(s.at(start + 0.875 * period + dwell).value, -amplitude * std::sqrt(0.5), 1e-12);
  EXPECT_EQ(s.at(start + period + dwell + 1e-9).value, 0.0);
  // Continuous value and rate across the dwell's ends; at its end the value
  // returns to zero (the steering stops there from its last slope).
  for (double joint : {start + 0.75 * period, start + 0.75 * period + dwell}) {
    const SignalValue a = s.at(joint - 1e-9), b = s.at(joint + 1e-9);
    EXPECT_NEAR(a.value, b.value, 1e-8) << joint;
    EXPECT_NEAR(a.rate, b.rate, 1e-6) << joint;
  }
  EXPECT_NEAR(s.at(start + period + dwell - 1e-9).value, 0.0, 1e-8);
  for (double t : {1.2, 1.9, 2.3, 2.75}) expectDerivatives(s, t);
}

TEST(Signals, ChirpSweepsItsFrequencyLinearly) {
  const double f0 = 0.2, f1 = 2.1, duration = 10.0;  // 11.5 cycles
  const ChirpSignal s(0.5, duration, 0.1, f0, f1);
  // The cycles: the integral of the frequency, duration (f0 + f1) / 2; one
  // upward zero crossing ends each whole cycle.
  int crossings = 0;
  double last = 0;
  for (double t = 0.5; t < 0.5 + duration; t += 1e-4) {
    const double v = s.at(t).value;
    if (last < 0 && v >= 0) ++crossings;  // upward zero crossings: one per cycle
    last = v;
  }
  EXPECT_EQ(crossings, static_cast<int>(std::floor(duration * (f0 + f1) / 2)));
  EXPECT_EQ(s.at(0.4).value, 0.0);
  EXPECT_EQ(s.at(0.5 + duration).value, 0.0);
  for (double t : {0.7, 3.3, 8.1, 10.2}) expectDerivatives(s, t);
}

}  // namespace
}  // namespace bdfcar::scenario
