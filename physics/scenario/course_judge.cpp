#include "scenario/course_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include "portable_math.h"

namespace bdfcar::scenario {

namespace {
constexpr double kApproachMargin = 10.0;  // m beside the lanes within which a car is at the course
}  // namespace

CourseJudge::CourseJudge(const Iso3888Course& course, double length, double width, const Eigen::Vector3d& centre)
    : course_(course), halfLength_(0.5 * length), halfWidth_(0.5 * width), centre_(centre), cones_(course.cones()),
      hit_(cones_.size(), false) {}

void CourseJudge::update(const vehicle::VehicleSample& s) {
  // Footprint in the ground plane: the chassis pose projected.
  const Eigen::Vector2d heading(pm::cos(s.yaw), pm::sin(s.yaw)), left(-heading.y(), heading.x());
  const Eigen::Vector3d c3 = s.chassisOrigin + s.chassisRotation * centre_;
  const Eigen::Vector2d c(c3.x(), c3.y());
  // In the course: over its length and near its lanes (a car driving past
  // it elsewhere on a proving ground has not entered it).
  double yMin = course_.lanes[0].centreY, yMax = yMin;
  for (const CourseLane& l : course_.lanes) {
    yMin = std::min(yMin, l.centreY - 0.5 * l.width);
    yMax = std::max(yMax, l.centreY + 0.5 * l.width);
  }
  const bool inside = c.x() + halfLength_ >= course_.startX && c.x() - halfLength_ <= course_.endX &&
                      c.y() >= yMin - kApproachMargin && c.y() <= yMax + kApproachMargin;
  if (inside && r_.entryTime < 0) r_.entryTime = s.t;
  if (!inside && r_.entryTime >= 0 && r_.exitTime < 0 && c.x() > course_.endX) r_.exitTime = s.t;
  if (!inside) return;
  r_.peakLateralAcceleration = std::max(r_.peakLateralAcceleration, std::abs(s.ay));
  for (double a : {-1.0, 1.0})
    for (double b : {-1.0, 1.0}) {
      const Eigen::Vector2d corner = c + a * halfLength_ * heading + b * halfWidth_ * left;
      if (!r_.leftLanes && !course_.contains(corner.x(), corner.y())) {
        r_.leftLanes = true;
        r_.passed = false;
        r_.firstFailureX = corner.x();
      }
    }
  for (size_t i = 0; i < cones_.size(); ++i) {
    if (hit_[i]) continue;
    const Eigen::Vector2d d = Eigen::Vector2d(cones_[i].x(), cones_[i].y()) - c;
    if (std::abs(d.dot(heading)) <= halfLength_ + kConeBaseRadius &&
        std::abs(d.dot(left)) <= halfWidth_ + kConeBaseRadius) {
      hit_[i] = true;
      ++r_.coneHits;
      r_.passed = false;
      r_.knockedCones.emplace_back(static_cast<int>(i), pm::atan2(heading.y(), heading.x()));
    }
  }
}

std::string courseVerdict(const CourseResult& r) {
  std::string why;
  char text[80];
  if (r.leftLanes) {
    std::snprintf(text, sizeof text, "left the lanes at x = %.1f m", r.firstFailureX);
    why = text;
  }
  if (r.coneHits > 0) {
    // The gates, each once, in the order along the course.
    std::vector<int> gates;
    for (const auto& [index, heading] : r.knockedCones) gates.push_back(coneGate(index));
    std::sort(gates.begin(), gates.end());
    gates.erase(std::unique(gates.begin(), gates.end()), gates.end());
    std::string list;
    for (size_t i = 0; i < gates.size(); ++i)
      list += (i == 0 ? "" : i + 1 == gates.size() ? " and " : ", ") + std::to_string(gates[i]);
    if (!why.empty()) why += ", ";
    why += std::to_string(r.coneHits) + (r.coneHits == 1 ? " cone" : " cones") + " hit at gate" +
           (gates.size() == 1 ? " " : "s ") + list;
  }
  if (!why.empty()) return "failed: " + why;
  if (r.entryTime < 0) return "not reached";
  if (r.exitTime < 0) return "not completed";
  return "passed";
}

}  // namespace bdfcar::scenario
