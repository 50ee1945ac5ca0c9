// Lap timing (physics/scenario/lap_timer.h) against times known in closed
// form: a point moving at a constant speed along a closed polygon crosses
// the start line every L / v and each of n equal sectors every L / (n v),
// whatever the sampling (samples every 10 ms, offset from the crossings);
// the delta to the best lap of a lap at another speed is x / v2 - x / v1 at
// distance x. A cut lap is timed but never the best, driving back over the
// line abandons the lap, a standing start is timed from the first sample.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scenario/lap_timer.h"

using namespace bdfcar;
using scenario::LapTimer;

namespace {

constexpr double kRadius = 100.0, kWidth = 12.0;
constexpr int kSides = 360;

std::vector<Eigen::Vector2d> polygon() {
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < kSides; ++i) {
    const double a = 2 * M_PI * i / kSides;
    p.emplace_back(kRadius * std::sin(a), kRadius - kRadius * std::cos(a));  // from (0, 0) heading +x, to the left
  }
  return p;
}

const double kSide = 2 * kRadius * std::sin(M_PI / kSides);
const double kLength = kSides * kSide;

// The point at distance s along the polygon (any s: it wraps), `aside` to the left of it.
Eigen::Vector2d along(double s, double aside = 0.0) {
  static const std::vector<Eigen::Vector2d> p = polygon();
  s = std::fmod(std::fmod(s, kLength) + kLength, kLength);
  const int i = std::min(kSides - 1, static_cast<int>(s / kSide));
  const Eigen::Vector2d a = p[i], d = (p[(i + 1) % kSides] - a).normalized();
  return a + (s - i * kSide) * d + aside * Eigen::Vector2d(-d.y(), d.x());
}

constexpr double kDt = 0.01, kT0 = 0.00371;  // samples off the crossings

}  // namespace

TEST(LapTimer, LapsAndSectorsAreLengthOverSpeedWhateverTheSampling) {
  LapTimer timer(polygon(), kWidth, 3);
  const double v = 17.3, s0 = 100.0;  // the out lap first: 100 m past the line
  int k = 0;
  for (; k * kDt * v < 3.5 * kLength - s0; ++k) timer.update(kT0 + k * kDt, along(s0 + k * kDt * v));
  ASSERT_EQ(timer.laps().size(), 2u);  // the out lap, then laps 1 and 2 completed
  for (const scenario::LapRecord& r : timer.laps()) {
    EXPECT_NEAR(r.time, kLength / v, 1e-9);
    ASSERT_EQ(r.sectors.size(), 3u);
    for (double s : r.sectors) EXPECT_NEAR(s, kLength / (3 * v), 1e-9);
    EXPECT_TRUE(r.valid);
  }
  EXPECT_EQ(timer.laps()[0].number, 1);
  EXPECT_EQ(timer.lap(), 3);
  EXPECT_EQ(timer.sector(), 2);  // half way round lap 3
  const double t = kT0 + (k - 1) * kDt;
  EXPECT_NEAR(timer.lapTime(t), (s0 + (k - 1) * kDt * v - 3 * kLength) / v, 1e-9);
  EXPECT_NEAR(timer.delta(t), 0.0, 1e-9);  // as fast as the best
  EXPECT_NEAR(timer.best()->time, kLength / v, 1e-9);
}

TEST(LapTimer, TheDeltaIsTheTimeLostAtTheSameDistance) {
  LapTimer timer(polygon(), kWidth, 2);
  const double v1 = 20.0, v2 = 18.0;
  // Lap 1 at v1 from a standing start (5 m past the line); lap 2 at v1 to
  // 20 m (the speed steady across the line, where crossings are
  // interpolated), then at v2.
  const double s0 = 5.0, xSlow = 20.0, tSlow = kT0 + (kLength + xSlow - s0) / v1;
  timer.update(kT0, along(s0));
  EXPECT_EQ(timer.lap(), 1);
  for (int k = 1;; ++k) {
    const double t = kT0 + k * kDt;
    const double s = t < tSlow ? s0 + (t - kT0) * v1 : kLength + xSlow + (t - tSlow) * v2;
    if (s > 1.8 * kLength) break;
    timer.update(t, along(s));
    if (timer.lap() == 2 && s > kLength + xSlow + 5.0) {
      // Lap 2 at x has run xSlow / v1 + (x - xSlow) / v2; lap 1, timed from s0, (x - s0) / v1.
      const double x = s - kLength;
      ASSERT_NEAR(timer.delta(t), xSlow / v1 + (x - xSlow) / v2 - (x - s0) / v1, 1e-9) << "at " << x << " m";
    }
  }
  ASSERT_EQ(timer.laps().size(), 1u);
  EXPECT_NEAR(timer.laps()[0].time, (kLength - s0) / v1, 1e-9);  // timed from the first sample
}

TEST(LapTimer, ACutLapIsNeverTheBestAndDrivingBackAbandonsTheLap) {
  LapTimer timer(polygon(), kWidth, 3);
  const double v = 15.0;
  double t = kT0, s = -20.0;
  auto drive = [&](double to, double aside, double speed) {
    for (; speed > 0 ? s < to : s > to; s += speed * kDt, t += kDt) timer.update(t, along(s, aside));
  };
  drive(kLength + 200.0, 0.0, v);                 // the out lap, then lap 1 (valid), into lap 2 ...
  drive(kLength + 230.0, 0.5 * kWidth + 1.5, v);  // ... cut: the centre of mass 1.5 m beyond the edge
  EXPECT_FALSE(timer.valid());
  drive(2 * kLength + 1.0, 0.0, 1.25 * v);        // lap 2 ends, faster but cut
  ASSERT_EQ(timer.laps().size(), 2u);
  EXPECT_TRUE(timer.laps()[0].valid);
  EXPECT_FALSE(timer.laps()[1].valid);
  EXPECT_LT(timer.laps()[1].time, timer.laps()[0].time);
  EXPECT_NEAR(timer.best()->time, kLength / v, 1e-9);  // a cut lap is not a best lap
  drive(3 * kLength + 1.0, 0.0, 1.25 * v);        // lap 3: faster and clean, the best
  ASSERT_EQ(timer.laps().size(), 3u);
  EXPECT_NEAR(timer.best()->time, kLength / (1.25 * v), 1e-9);
  // Back over the line: lap 4 is abandoned; forward again, the crossing
  // starts lap 5 and lap 4 is not recorded.
  drive(3 * kLength - 20.0, 0.0, -5.0);
  EXPECT_LT(timer.lapTime(t), 0.0);
  drive(3 * kLength + 100.0, 0.0, v);
  EXPECT_EQ(timer.laps().size(), 3u);
  EXPECT_EQ(timer.lap(), 5);
  // lapClock: a timing screen's m:ss.sss.
  EXPECT_EQ(scenario::lapClock(112.3414), "1:52.341");
  EXPECT_EQ(scenario::lapClock(59.9996), "1:00.000");
}

// A copy (a run's snapshot) goes on exactly as the original.
TEST(LapTimer, ACopyContinuesAsTheOriginal) {
  LapTimer a(polygon(), kWidth, 3);
  const double v = 25.0;
  int k = 0;
  for (; k < 2000; ++k) a.update(kT0 + k * kDt, along(50.0 + k * kDt * v));
  LapTimer b = a;
  for (; k < 8000; ++k) {
    a.update(kT0 + k * kDt, along(50.0 + k * kDt * v));
    b.update(kT0 + k * kDt, along(50.0 + k * kDt * v));
  }
  ASSERT_EQ(a.laps().size(), b.laps().size());
  ASSERT_GE(a.laps().size(), 2u);
  for (size_t i = 0; i < a.laps().size(); ++i) EXPECT_EQ(a.laps()[i].time, b.laps()[i].time);
  EXPECT_EQ(a.distance(), b.distance());
}

// The ghost: on lap 2, at each time into the lap, the best lap's car where
// it was at that time into its lap (lap 1 at v1 from a standing start at s0:
// s0 + v1 tau along the line), whatever speed lap 2 goes at; none on the
// out lap, none once the lap is slower than the whole best lap.
TEST(LapTimer, TheGhostIsTheBestLapAtTheSameTimeIntoTheLap) {
  LapTimer timer(polygon(), kWidth, 3);
  const double v1 = 20.0, v2 = 17.0, s0 = 5.0;
  auto heading = [](double s) {
    const Eigen::Vector2d d = along(s + 1e-6) - along(s);
    return std::atan2(d.y(), d.x());
  };
  EXPECT_FALSE(timer.ghost(kT0).has_value());
  const double tLap2 = kT0 + (kLength - s0) / v1;
  int checked = 0;
  double last = kT0;
  for (int k = 0;; ++k) {
    const double t = kT0 + k * kDt;
    const double s = t < tLap2 ? s0 + (t - kT0) * v1 : kLength + (t - tLap2) * v2;
    if (s > 2 * kLength - 1.0) break;
    timer.update(t, along(s), heading(s));
    last = t;
    if (timer.lap() < 2) {
      EXPECT_FALSE(timer.ghost(t).has_value());
      continue;
    }
    const double tau = t - tLap2;  // into lap 2 (the crossing at constant speed: exact)
    const std::optional<scenario::GhostPose> g = timer.ghost(t);
    if (tau > (kLength - s0) / v1 - 0.2) continue;  // the best lap's end
    ASSERT_TRUE(g.has_value()) << "tau " << tau;
    // The ghost's points, kGhostStep apart (c = 2 m at v1), are joined by
    // straight lines: across a chord the line turns by at most c / R, so the
    // chord strays from it by less than c^2 / (2 R) = 2 cm.
    const Eigen::Vector2d expected = along(s0 + v1 * tau);
    const double stray = std::pow(v1 * LapTimer::kGhostStep, 2) / (2 * kRadius);
    EXPECT_NEAR(g->x, expected.x(), stray) << "tau " << tau;
    EXPECT_NEAR(g->y, expected.y(), stray) << "tau " << tau;
    EXPECT_NEAR(std::remainder(g->yaw - heading(s0 + v1 * tau), 2 * M_PI), 0.0, 0.02) << "tau " << tau;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  // Lap 2 (slower) went on past the best lap's time: no ghost then.
  ASSERT_GT(last - tLap2, (kLength - s0) / v1);
  EXPECT_FALSE(timer.ghost(last).has_value());
}
