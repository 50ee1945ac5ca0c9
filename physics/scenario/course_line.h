// A line through an ISO 3888 course that a car of a given footprint can
// follow without touching a cone, with the least peak curvature found
// (what limits the speed): computed from the course geometry, not drawn.
//
// The line is straight in each lane and changes lane along quintic
// smoothsteps (zero slope and curvature at both ends, so the steering
// starts and ends without a jump): y = y0 + (y1 - y0) s(u), u = (x - xs) /
// (xe - xs), s = 10 u^3 - 15 u^4 + 6 u^5, whose largest |y''| is 10 / sqrt(3)
// |y1 - y0| / (xe - xs)^2. Each lane change's start and end (anywhere in the
// lanes it joins) and the line's place across each lane are searched on a
// grid; a candidate is kept only when the car's footprint, grown by a margin
// on every side and carried along the line with the line's heading, passes
// the course judge (course_judge.h: no corner out of a lane, no cone hit).
#pragma once

#include "scenario/iso3888_course.h"

namespace bdfcar::scenario {

struct CourseLine {
  // The entry, side and exit lanes' lines, and the two lane changes' extents.
  double yEntry = 0, ySide = 0, yExit = 0;
  double xs1 = 0, xe1 = 0, xs2 = 0, xe2 = 0;
  bool feasible = false;     // some candidate passed the judge
  double margin = 0;         // m, the footprint grown by this on every side for it
  double peakCurvature = 0;  // 1/m, the larger lane change's
  double y(double x) const;
  double slope(double x) const;      // dy/dx
  double curvature(double x) const;  // signed, 1/m
};

// length, width: the car's footprint (m), its centre `centre` (m, forward
// and left) from the point that follows the line; margin: grown by this on
// every side (m), for the driver's tracking error and the body's sideslip:
// the margin asked for, or the largest of its halvings (down to 0) with a
// clean line. With none, the lane centres joined over the free sections
// (feasible = false).
CourseLine computeCourseLine(const Iso3888Course& course, double length, double width, const Eigen::Vector2d& centre,
                             double margin);

}  // namespace bdfcar::scenario
