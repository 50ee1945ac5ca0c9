// The ISO 3888-1 course judge (scenario/course_judge.h) on a footprint driven
// straight along y = y0 through the course: the cones it hits are those whose
// centre lies within half the width plus the cone's base radius of the line
// (plane geometry, counted here independently), each once and knocked toward
// the car's heading; leaving the lanes fails the run.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <Eigen/Geometry>

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

// As the standards judge: a run fails when a corner leaves a lane or a cone
// is hit, whichever comes first. Single poses scattered over the ISO 3888-2
// course, each judged alone and against the two rules computed here from
// plane geometry; among them poses with every corner inside the lanes whose
// side still knocks a cone at a lane's end (they used to pass), and the
// verdict names the gates of the cones hit (the pair across a lane at one x).
TEST(CourseJudge, ACornerOutOrAConeDownFailsTheRunAndTheVerdictNamesTheGates) {
  const double width = 1.8, length = 4.5;
  const scenario::Iso3888Course course = scenario::makeIso3888Course(width, 0.0, 0.0, 2);
  const std::vector<Eigen::Vector3d> cones = course.cones();
  // Gates by geometry: the distinct cone x positions of each lane, counted along the course.
  std::vector<std::pair<double, int>> gateX;
  int gate = 0;
  for (const scenario::CourseLane& l : course.lanes) {
    std::set<double> xs;
    for (const Eigen::Vector3d& c : cones)
      if (c.x() >= l.x0 - 1e-9 && c.x() <= l.x1 + 1e-9 && std::abs(std::abs(c.y() - l.centreY) - (0.5 * l.width + scenario::kConeBaseRadius)) < 1e-9)
        xs.insert(c.x());
    for (double x : xs) gateX.emplace_back(x, ++gate);
  }
  int insideButHit = 0, clean = 0, out = 0;
  unsigned seed = 12345;
  auto uniform = [&seed](double a, double b) {
    seed = seed * 1103515245u + 12345u;
    return a + (b - a) * ((seed >> 8) & 0xffff) / 65535.0;
  };
  for (int k = 0; k < 4000; ++k) {
    const double x = uniform(course.startX, course.endX), yaw = uniform(-0.35, 0.35);
    const double y = course.referenceY(x) + uniform(-0.8, 0.8);
    const Eigen::Vector2d c(x, y), heading(std::cos(yaw), std::sin(yaw)), left(-heading.y(), heading.x());
    bool inside = true;
    for (double a : {-1.0, 1.0})
      for (double b : {-1.0, 1.0}) {
        const Eigen::Vector2d p = c + 0.5 * length * a * heading + 0.5 * width * b * left;
        const scenario::CourseLane* l = course.laneAt(p.x());
        if (l && std::abs(p.y() - l->centreY) > 0.5 * l->width) inside = false;
      }
    std::set<int> gatesHit;
    int hits = 0;
    for (const Eigen::Vector3d& cone : cones) {
      const Eigen::Vector2d d = cone.head<2>() - c;
      if (std::abs(d.dot(heading)) <= 0.5 * length + scenario::kConeBaseRadius &&
          std::abs(d.dot(left)) <= 0.5 * width + scenario::kConeBaseRadius) {
        ++hits;
        for (const auto& [gx, g] : gateX)
          if (std::abs(gx - cone.x()) < 1e-9) gatesHit.insert(g);
      }
    }
    scenario::CourseJudge judge(course, length, width, Eigen::Vector3d::Zero());
    vehicle::VehicleSample s;
    s.chassisRotation = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    s.chassisOrigin = Eigen::Vector3d(x, y, 0.5);
    s.yaw = yaw;
    judge.update(s);
    const scenario::CourseResult& r = judge.result();
    ASSERT_EQ(r.leftLanes, !inside) << "x " << x << " y " << y << " yaw " << yaw;
    ASSERT_EQ(r.coneHits, hits);
    ASSERT_EQ(r.passed, inside && hits == 0);
    const std::string verdict = scenario::courseVerdict(r);
    if (hits > 0) {
      std::string gates;
      int n = 0;
      for (int g : gatesHit) gates += (n++ == 0 ? "" : n == static_cast<int>(gatesHit.size()) ? " and " : ", ") + std::to_string(g);
      EXPECT_NE(verdict.find(std::to_string(hits) + (hits == 1 ? " cone hit at gate" : " cones hit at gate")), std::string::npos) << verdict;
      EXPECT_NE(verdict.find(gates), std::string::npos) << verdict << " (gates " << gates << ")";
    }
    if (!r.passed) EXPECT_EQ(verdict.rfind("failed: ", 0), 0u) << verdict;
    else EXPECT_EQ(verdict, "not completed");  // entered, not through the exit gate
    insideButHit += inside && hits > 0;
    clean += inside && hits == 0;
    out += !inside;
  }
  // Each kind of pose occurs: the comparison is not of empty sets.
  EXPECT_GT(insideButHit, 5);
  EXPECT_GT(clean, 100);
  EXPECT_GT(out, 100);
  // Never entered: "not reached".
  EXPECT_EQ(scenario::courseVerdict(scenario::CourseResult{}), "not reached");
}
