// Judges a drive through the ISO 3888-1 course: a run fails when any corner
// of the car's footprint leaves a lane section; cones inside the footprint
// (plus the cone's base radius) count as hit, each once. Also the peak
// lateral acceleration and the times the car entered and left the course.
#pragma once

#include <utility>
#include <vector>

#include "scenario/iso3888_course.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

struct CourseResult {
  bool passed = true;
  int coneHits = 0;
  double peakLateralAcceleration = 0;  // |a_y|, m/s^2, inside the course
  double entryTime = -1, exitTime = -1;  // s; -1 = not yet
  double firstFailureX = 0;            // where a corner first left the course, m
  // The cones hit, in the order of Iso3888Course::cones(), each with the
  // car's heading when it was hit (rad: the way it is knocked over).
  std::vector<std::pair<int, double>> knockedCones;
};

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
