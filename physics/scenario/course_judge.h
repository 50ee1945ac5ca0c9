// Judges a drive through an ISO 3888 course as the standards do: a run fails
// when any corner of the car's footprint leaves a lane section or a cone is
// hit (a cone down is a failed run, ISO 3888-1 and -2); cones inside the
// footprint (plus the cone's base radius) count as hit, each once. Also the
// peak lateral acceleration and the times the car entered and left the course.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scenario/iso3888_course.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

struct CourseResult {
  bool passed = true;       // no corner out of a lane and no cone hit (so far)
  bool leftLanes = false;   // a corner of the footprint left a lane section
  int coneHits = 0;
  double peakLateralAcceleration = 0;  // |a_y|, m/s^2, inside the course
  double entryTime = -1, exitTime = -1;  // s; -1 = not yet
  double firstFailureX = 0;            // where a corner first left the course, m
  // The cones hit, in the order of Iso3888Course::cones(), each with the
  // car's heading when it was hit (rad: the way it is knocked over).
  std::vector<std::pair<int, double>> knockedCones;
};

// The verdict in words: "passed", "failed: 2 cones hit at gates 3 and 4",
// "failed: left the lanes at x = 35.2 m", "not completed" (entered, not
// through the exit gate) or "not reached" (never entered).
std::string courseVerdict(const CourseResult& r);
// The gate a cone of Iso3888Course::cones() stands at (1 = the entry gate).
inline int coneGate(int coneIndex) { return coneIndex / 2 + 1; }

class CourseJudge {
 public:
  // Footprint: length x width of the car, centred at `centre` (chassis frame).
  CourseJudge(const Iso3888Course& course, double length, double width, const Eigen::Vector3d& centre);
  void update(const vehicle::VehicleSample& s);
  const CourseResult& result() const { return r_; }
  bool finished() const { return r_.exitTime >= 0; }

 private:
  Iso3888Course course_;
  double halfLength_, halfWidth_;
  Eigen::Vector3d centre_;
  std::vector<Eigen::Vector3d> cones_;
  std::vector<bool> hit_;
  CourseResult r_;
};

}  // namespace bdfcar::scenario
