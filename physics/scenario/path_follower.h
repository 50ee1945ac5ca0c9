// A look-ahead path follower, as a driver would steer: pure pursuit toward
// the point of the reference path a look-ahead distance ahead (kinematic
// bicycle curvature), scaled by the car's understeer, which the driver
// learns while driving: the ratio of the curvature asked for to the
// curvature obtained (yaw rate / speed), low-pass filtered. The speed is
// held by the PI controller separately.
#pragma once

#include <functional>

#include "scenario/driver_paths.h"

namespace bdfcar::scenario {

struct PathFollowerParams {
  double lookAheadTime = 0.9;      // s
  double minLookAhead = 5.0;       // m
  double wheelbase = 2.46;         // m
  double steerPerRoadWheel = 1.0;  // normalised steering per rad of road-wheel angle
  double learningTime = 0.5;       // s, time constant of the understeer estimate
};

class PathFollower {
 public:
  // What the follower has learnt and last asked for: its run state.
  struct State {
    double gain = 1.0;           // curvature asked / curvature obtained
    double lastCurvature = 0.0;  // curvature asked for at the last call
    bool operator==(const State&) const = default;
  };
  // state: where it lives (a RunState's).
  PathFollower(const PathFollowerParams& p, PathTarget target, State& state)
      : p_(p), target_(std::move(target)), s_(state) {}
  // Normalised steering [-1, 1] for a vehicle at (x, y) with heading yaw,
  // speed v and yaw rate r; dt is the time since the last call.
  double steer(double x, double y, double yaw, double v, double yawRate, double dt);
  double understeerGain() const { return s_.gain; }

 private:
  PathFollowerParams p_;
  PathTarget target_;
  State& s_;
};

}  // namespace bdfcar::scenario
