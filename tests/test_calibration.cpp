// The standards' calibrations (scenario/calibration.h) on the linear
// single-track car, whose answers are closed forms: the ISO 7401 step for
// 4 m/s^2, FMVSS 126's A from the slowly increasing steer (the ramp's
// response lags the steady one by the model's own lag), the ISO 4138
// steering for a 40 m circle; and the rule's amplitude series and verdict.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario/calibration.h"
#include "single_track_drive.h"

using namespace bdfcar;

namespace {

constexpr double kG = 9.80665;

vehicle::SingleTrack car() {
  vehicle::SingleTrack c;
  c.mass = 1600;
  c.yawInertia = 2700;
  c.a = 1.2;
  c.b = 1.5;
  c.frontStiffness = 90000;
  c.rearStiffness = 120000;
  c.roadWheelPerSteer = 0.5;  // rad at full input
  return c;
}

}  // namespace

// ISO 7401: the step (normalised input) whose steady lateral acceleration
// is 4 m/s^2 at 80 km/h: 4 / (G0 k), G0 = u^2 / (L + K u^2).
TEST(Calibration, Iso7401StepForFourMetresPerSecondSquared) {
  const vehicle::SingleTrack c = car();
  const double u = 80 / 3.6;
  auto steady = [&](double level) {
    const scenario::TimeHistory h = test::drive(c, u, 6.0, [&](double) { return c.roadWheelPerSteer * level; }, 1.0);
    return h.ay.back();
  };
  const scenario::Calibration cal = scenario::calibrate(steady, 4.0, 0.3, 0.001);
  ASSERT_TRUE(cal.converged);
  const double closed = 4.0 / (c.steadyLateralGain(u) * c.roadWheelPerSteer);
  EXPECT_NEAR(cal.input, closed, 0.01 * closed);
  EXPECT_LE(cal.tries.size(), 4u);
  // A target beyond the input's limit: the closest it gets, not converged.
  const scenario::Calibration far = scenario::calibrate(steady, 1e3, 0.3, 0.001);
  EXPECT_FALSE(far.converged);
  EXPECT_EQ(far.input, 1.0);
}

// FMVSS 126 S7.6: 13.5 deg/s of steering wheel at 80 km/h, steering ratio
// 16; the line through 0.1-0.375 g gives at 0.3 g the steady angle plus the
// ramp's lag: ratio (0.3 g / G0 + rate lag).
TEST(Calibration, SlowlyIncreasingSteerGivesTheAngleAtPointThreeG) {
  const vehicle::SingleTrack c = car();
  const double u = 80 / 3.6, ratio = 16.0, rate = 13.5 * M_PI / 180 / ratio;  // rad/s of road-wheel angle
  const scenario::TimeHistory h = test::drive(c, u, 8.0, [&](double t) { return rate * t; }, ratio * 180 / M_PI);
  const double A = scenario::sisAngleAt(h);
  const double closed = ratio * (0.3 * kG / c.steadyLateralGain(u) + rate * c.rampLag(u)) * 180 / M_PI;
  EXPECT_NEAR(A, closed, 0.01 * closed);
  // Too short a ramp to reach the window: no answer.
  EXPECT_TRUE(std::isnan(scenario::sisAngleAt(test::drive(c, u, 0.3, [&](double t) { return rate * t; }, 1.0))));
}

// ISO 4138: the steering for a 40 m circle at 20 km/h: the path's curvature
// r / u = delta / (L + K u^2).
TEST(Calibration, Iso4138SteeringForAFortyMetreCircle) {
  const vehicle::SingleTrack c = car();
  const double u = 20 / 3.6;
  auto curvature = [&](double level) {
    const scenario::TimeHistory h = test::drive(c, u, 8.0, [&](double) { return c.roadWheelPerSteer * level; }, 1.0);
    return h.yawRate.back() / u;
  };
  const scenario::Calibration cal = scenario::calibrate(curvature, 1.0 / 40, 0.05, 0.001);
  ASSERT_TRUE(cal.converged);
  const double closed = (c.wheelbase() + c.understeerGradient() * u * u) / 40 / c.roadWheelPerSteer;
  EXPECT_NEAR(cal.input, closed, 0.01 * closed);
}

// S7.9: 1.5 A in steps of 0.5 A; the last the greater of 6.5 A and 270
// deg, or 300 deg where 6.5 A passes 300 deg.
TEST(Calibration, Fmvss126SeriesFollowsTheRule) {
  const std::vector<double> a = scenario::fmvss126Amplitudes(20.0);
  ASSERT_GE(a.size(), 3u);
  EXPECT_DOUBLE_EQ(a[0], 30.0);
  EXPECT_DOUBLE_EQ(a[1], 40.0);
  EXPECT_DOUBLE_EQ(a.back(), 270.0);  // 6.5 A = 130 < 270
  EXPECT_DOUBLE_EQ(a[a.size() - 2], 260.0);
  const std::vector<double> b = scenario::fmvss126Amplitudes(50.0);  // 6.5 A = 325 > 300
  EXPECT_DOUBLE_EQ(b.back(), 300.0);
  EXPECT_DOUBLE_EQ(b[b.size() - 2], 275.0);  // 5.5 A; 6.0 A = 300 is the last
  const std::vector<double> c = scenario::fmvss126Amplitudes(44.0);  // 6.5 A = 286: the greater of it and 270
  EXPECT_DOUBLE_EQ(c.back(), 286.0);
  EXPECT_TRUE(scenario::fmvss126Amplitudes(0.0).empty());
}

// The verdict: the first run that misses a yaw-rate limit, or the
// displacement in a run of 5 A or more (not below).
TEST(Calibration, Fmvss126VerdictNamesTheFirstMiss) {
  scenario::SineWithDwellMetrics good;
  good.valid = good.passYaw1000 = good.passYaw1750 = good.passDisplacement = true;
  scenario::SineWithDwellMetrics shortOfDisplacement = good;
  shortOfDisplacement.passDisplacement = false;
  shortOfDisplacement.lateralDisplacement = 1.5;
  scenario::SineWithDwellMetrics spins = good;
  spins.passYaw1000 = false;
  spins.yawRatio1000 = 60.0;
  const double A = 20;
  EXPECT_TRUE(scenario::fmvss126Verdict({30, 40}, {good, shortOfDisplacement}, A).pass);  // 40 < 5 A
  const scenario::SeriesVerdict d = scenario::fmvss126Verdict({90, 100}, {good, shortOfDisplacement}, A);
  EXPECT_FALSE(d.pass);
  EXPECT_NE(d.why.find("100.0 deg"), std::string::npos) << d.why;
  const scenario::SeriesVerdict y = scenario::fmvss126Verdict({30, 40, 50}, {good, spins, good}, A);
  EXPECT_FALSE(y.pass);
  EXPECT_NE(y.why.find("60.0 %"), std::string::npos) << y.why;
}
