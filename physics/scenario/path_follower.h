// A look-ahead path follower: steers toward the point of a reference path
// y(x) a look-ahead distance ahead of the vehicle (pure pursuit on the
// kinematic bicycle), the speed is held by the PI controller separately.
#pragma once

#include <functional>

namespace bdfcar::scenario {

struct PathFollowerParams {
  double lookAheadTime = 0.9;  // s
  double minLookAhead = 5.0;   // m
  double wheelbase = 2.46;     // m
  double steerPerRoadWheel = 1.0;  // normalised steering per rad of road-wheel angle
};

class PathFollower {
 public:
  PathFollower(const PathFollowerParams& p, std::function<double(double)> pathY) : p_(p), path_(std::move(pathY)) {}
  // Normalised steering [-1, 1] for a vehicle at (x, y) with heading yaw and speed v.
  double steer(double x, double y, double yaw, double v) const;

 private:
  PathFollowerParams p_;
  std::function<double(double)> path_;
};

}  // namespace bdfcar::scenario
