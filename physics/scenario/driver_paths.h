// What the path-following driver (path_follower.h) steers along: the point
// of a reference path a look-ahead distance ahead of the car.
//  - a lane-change course's driving line (iso3888_course.h), which runs
//    along +x: the point L ahead along x;
//  - any path given as a polyline of (x, y) points (a CSV file), open or
//    closed: the point L further along the polyline than the car's nearest
//    point on it (the first nearest over the whole polyline, so the driver
//    keeps no state of its own: a path that crosses itself may be taken at
//    the crossing);
//  - a circle of a given radius (ISO 4138's constant radius): the point L
//    further along the arc, counter-clockwise for a left turn.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace bdfcar::scenario {

// (x, y, yaw, look-ahead distance) -> the target point.
using PathTarget = std::function<Eigen::Vector2d(double x, double y, double yaw, double lookAhead)>;

class PolylinePath {
 public:
  // At least two points, no two consecutive ones equal (the loader checks).
  PolylinePath(std::vector<Eigen::Vector2d> points, bool closed);
  Eigen::Vector2d target(double x, double y, double lookAhead) const;
  // The signed distance of (x, y) from the path (its first nearest point), + left of its direction.
  double offset(double x, double y) const;
  double length() const { return s_.back(); }

 private:
  Eigen::Vector2d at(double s) const;  // the point at arc length s (wrapped on a closed path, clamped on an open one)
  // The arc length of the first nearest point of segment i or earlier among
  // those searched: a uniform grid of cells, each listing the segments whose
  // box overlaps it, searched ring by ring outwards from the car's cell
  // until no unsearched cell can hold a nearer segment (a lap's polyline of
  // hundreds of points costs a few segments a query, not all of them). The
  // answer is the whole scan's, bit for bit: the same distance per segment,
  // the same tie (the lowest index); a car outside the grid scans them all.
  struct Nearest {
    double dist = 1e300, s = 0;
    size_t index = 0;
  };
  void consider(size_t segment, const Eigen::Vector2d& q, Nearest& n) const;
  Nearest scanAll(const Eigen::Vector2d& q) const;
  Nearest nearest(const Eigen::Vector2d& q) const;
  void buildGrid();
  std::vector<Eigen::Vector2d> p_;
  std::vector<double> s_;  // arc length at each point
  bool closed_;
  Eigen::Vector2d gridOrigin_ = Eigen::Vector2d::Zero();
  double cell_ = 1;
  int cols_ = 0, rows_ = 0;
  std::vector<int> cellStart_;     // (cols * rows + 1) offsets into cellSegments_
  std::vector<int> cellSegments_;  // segment indices, by cell, ascending
};

struct CirclePath {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 1;
  double direction = 1;  // +1 counter-clockwise (turning left), -1 clockwise
  Eigen::Vector2d target(double x, double y, double lookAhead) const;
};

}  // namespace bdfcar::scenario
