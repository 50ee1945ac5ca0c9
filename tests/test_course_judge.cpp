// The ISO 3888-1 course judge (scenario/course_judge.h) on a footprint driven
// straight along y = y0 through the course: the cones it hits are those whose
// centre lies within half the width plus the cone's base radius of the line
// (plane geometry, counted here independently), each once and knocked toward
// the car's heading; leaving the lanes fails the run.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "scenario/course_judge.h"

using namespace bdfcar;

TEST(CourseJudge, AStraightPassHitsTheConesWithinHalfTheWidthOfItsLine) {
  const double width = 1.9, length = 4.6;
  const scenario::Iso3888Course course = scenario::makeIso3888Course(width, 50.0, 0.0);
  const std::vector<Eigen::Vector3d> cones = course.cones();
  std::size_t hitsInAll = 0;
  for (double y0 : {0.0, 1.0, 3.5}) {
    SCOPED_TRACE(y0);
    scenario::CourseJudge judge(course, length, width, Eigen::Vector3d::Zero());
    // Expected: every cone within the swept band, by geometry.
    std::set<int> expected;
    for (std::size_t i = 0; i < cones.size(); ++i)
      if (std::abs(cones[i].y() - y0) <= 0.5 * width + scenario::kConeBaseRadius && cones[i].x() >= course.startX - 1.0)
        expected.insert(static_cast<int>(i));
    vehicle::VehicleSample s;
    s.chassisRotation = Eigen::Matrix3d::Identity();
    s.yaw = 0;
    for (double x = course.startX - 10; x <= course.endX + 10; x += 0.05) {
      s.t = x / 20.0;
      s.chassisOrigin = Eigen::Vector3d(x, y0, 0.5);
      judge.update(s);
    }
    const scenario::CourseResult& r = judge.result();
    std::set<int> knocked;
    for (const auto& [index, heading] : r.knockedCones) {
      EXPECT_TRUE(knocked.insert(index).second) << "cone " << index << " counted twice";
      EXPECT_EQ(heading, 0.0);
    }
    EXPECT_EQ(knocked, expected);
    EXPECT_EQ(r.coneHits, static_cast<int>(expected.size()));
    hitsInAll += expected.size();
    // A straight line cannot follow the offset lane: the run fails, and one that hits no cone still fails.
    EXPECT_FALSE(r.passed);
    EXPECT_GE(r.exitTime, 0.0);
  }
  EXPECT_GE(hitsInAll, 4u);  // the lines cross cone rows: the comparison is not of empty sets
}
