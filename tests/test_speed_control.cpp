// The speed hold (scenario/speed_controller.h): the PI law below the
// driveline's limit, conditional integration at the limit, its phases and
// its target ramp, against the closed forms.
#include <gtest/gtest.h>

#include "scenario/speed_controller.h"

using namespace bdfcar::scenario;

// Below the limit: T = Kp e + Ki integral(e), the integral by explicit Euler.
TEST(SpeedControl, IsThePiLawBelowTheLimit) {
  double state = 0;
  SpeedController c(SpeedProfile{20.0}, {600, 300}, state, 1000.0);
  const double h = 0.01;
  double integral = 0;
  for (int i = 0; i < 100; ++i) {
    const double vx = 19.9 + 0.0005 * i;
    const double e = 20.0 - vx;
    EXPECT_DOUBLE_EQ(c.torque(vx, h, i * h), 600 * e + 300 * integral);
    integral += e * h;
  }
}

// Held at the limit by a speed it cannot reach (a brake, a slope), the hold
// gives the limit and its integral does not grow: once the speed passes the
// target the torque is the proportional part alone. Without anti-windup the
// integral of 10 s of a 10 m/s error (100 m) would give 30000 N m more.
TEST(SpeedControl, DoesNotWindUpAtTheDrivelineLimit) {
  double state = 0;
  SpeedController c(SpeedProfile{20.0}, {600, 300}, state, 1000.0);
  for (int i = 0; i < 1000; ++i) EXPECT_DOUBLE_EQ(c.torque(10.0, 0.01, i * 0.01), 1000.0);
  EXPECT_DOUBLE_EQ(c.integral(), 0.0);
  EXPECT_DOUBLE_EQ(c.torque(21.0, 0.01, 10.0), -600.0);
  // Saturated the other way, the integral that brings it back still counts.
  double other = -10.0;  // its state: T = 600 * 1 - 3000: saturated at -1000, the error (+1) reduces the integral's pull
  SpeedController d(SpeedProfile{20.0}, {600, 300}, other, 1000.0);
  EXPECT_DOUBLE_EQ(d.torque(19.0, 0.01, 0.0), -1000.0);
  EXPECT_DOUBLE_EQ(d.integral(), -10.0 + 0.01);
}

// Phases: no torque outside [start, end), a fresh integral when it takes
// over; the target ramps linearly between its two values.
TEST(SpeedControl, ActsInItsPhaseAndRampsItsTarget) {
  SpeedProfile p{10.0};
  p.start = 1.0;
  p.end = 3.0;
  p.rampTo = 30.0;
  p.rampStart = 1.0;
  p.rampDuration = 4.0;
  double state = 0;
  SpeedController c(p, {600, 300}, state);
  EXPECT_EQ(c.torque(5.0, 0.01, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(c.torque(10.0, 0.01, 1.0), 0.0);  // on target at the start
  EXPECT_DOUBLE_EQ(c.target(2.0), 15.0);
  EXPECT_DOUBLE_EQ(c.target(9.0), 30.0);
  c.torque(10.0, 0.5, 2.0);
  EXPECT_GT(c.integral(), 0.0);
  EXPECT_EQ(c.torque(10.0, 0.01, 3.0), 0.0);  // ended: coasting
  EXPECT_EQ(c.integral(), 0.0);
}
