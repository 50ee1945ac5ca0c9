// Geometry of the ISO 3888 lane-change courses. Part 1 (double lane change), as this project
// specifies it: five sections of 15 / 30 / 25 / 25 / 15 m; lane widths
// 1.1 w + 0.25 (entry), 1.2 w + 0.25 (side lane), 1.3 w + 0.25 (exit), w the
// vehicle width. The right-hand cone line of the entry lane is the datum: the
// side lane's centre lies 3.5 m + half its width to the left of it, and the
// exit lane shares the entry lane's right-hand cone line. The course starts at
// x = startX; the entry lane is centred on y = centreY. Plain geometry, used
// by the path follower, the pass/fail judge and the renderer alike.
//
// Part 2 (obstacle avoidance, ISO 3888-2:2011 Table 1): sections of 12 /
// 13.5 / 11 / 12.5 / 12 m (61 m); lane widths 1.1 w + 0.25 (entry), w + 1
// (side lane), 1.3 w + 0.25 but at most 3 m (exit); the side lane's
// right-hand limit lies 1 m to the left of the entry lane's left-hand limit,
// and the exit lane shares the entry lane's right-hand limit.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace bdfcar::scenario {

// Base radius of a course cone, m. The lane limits are tangent to the cones'
// bases (ISO 3888): cone centres sit this far outside the lane.
constexpr double kConeBaseRadius = 0.15;

struct CourseLane {
  double x0 = 0, x1 = 0;   // extent along x, m
  double centreY = 0;      // m
  double width = 0;        // m
};

struct Iso3888Course {
  int part = 1;                     // ISO 3888-1 or -2
  double vehicleWidth = 0;
  std::array<CourseLane, 3> lanes;  // entry, side, exit (sections 1, 3, 5)
  double startX = 0, endX = 0;

  // Lane holding x, or nullptr in the free transition sections 2 and 4.
  const CourseLane* laneAt(double x) const;
  // True if the point is inside the course (always true in sections 2 and 4).
  bool contains(double x, double y) const;
  // Cone positions (ground level) along both limits of the three lanes,
  // spaced at most `spacing` m apart, kConeBaseRadius outside the limits:
  // gate by gate along the course, the pair across the lane (left, right),
  // so cones 2k and 2k + 1 make gate k + 1.
  std::vector<Eigen::Vector3d> cones(double spacing = 2.5) const;
  // A smooth reference centreline y(x) through the lane centres (cosine blends over sections 2 and 4).
  double referenceY(double x) const;
  // A driving line for a car `carWidth` wide: straight through each lane,
  // using `marginUse` (0..1) of the lane's spare width on the side the next
  // lane lies, with cosine transitions over sections 2 and 4 (flat at the
  // lane ends, so the car's corners follow the line into the next lane).
  double drivingLineY(double x, double carWidth, double marginUse) const;
};

Iso3888Course makeIso3888Course(double vehicleWidth, double startX = 0.0, double centreY = 0.0, int part = 1);

}  // namespace bdfcar::scenario
