// Where each camera mode puts the eye, from the chassis pose alone (no OSG):
// chase (behind, yaw only, its heading following the car's on a damped
// spring), hood (rigid on the car), orbit (around the car), top-down (world x
// to the right).
#pragma once

#include <Eigen/Core>
#include <limits>

#include "render/scene.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::render {

// The haze (the scene's fog, by eye depth) from kHazeStart to kHazeEnd, m.
// Deeper than its end everything is drawn in the fog's colour, which is the
// clear colour: the far plane is put there, and what lies beyond it is
// culled rather than drawn (at the rough road, a third of the grass's
// drawables).
constexpr double kHazeStart = 150.0, kHazeEnd = 1500.0;

struct CameraPose {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::UnitX(), up = Eigen::Vector3d::UnitZ();
  double fovYDeg = 45.0;  // vertical field of view
  double zNear = 0.25, zFar = kHazeEnd;
};

struct OrbitState {
  double yaw = 2.4;        // rad, around the car, relative to its heading (pi = from behind)
  double pitch = 0.32;     // rad above the horizon
  double distance = 8.5;   // m from the car
};

// Heading angle of the chassis x axis projected on the ground plane, rad.
double headingOf(const vehicle::BodyPose& chassis);

// The chase camera's heading: it follows the car's on a critically damped
// spring (natural frequency kOmega), so that a turn shows as the car yawing
// in the picture (a steady turn at yaw rate r lags by 2 r / kOmega) instead
// of the world turning round a car fixed on screen. Advanced exactly over
// each frame's simulated time (the car's heading held over the frame); a jump back in time (reset, rewind) or of more than
// kSnapAfter snaps it to the car.
class ChaseHeading {
 public:
  static constexpr double kOmega = 3.0;       // rad/s: a step settles in ~1.5 s, 2 r / kOmega = 0.23 rad at 20 deg/s
  static constexpr double kSnapAfter = 1.0;   // s
  double update(double carHeading, double time);
  double heading() const { return heading_; }

 private:
  bool valid_ = false;
  double heading_ = 0, rate_ = 0, time_ = 0;
};

// Eye, target and up vector of the camera for this mode and chassis pose;
// the chase camera looks along chaseHeading (NaN: the car's own).
CameraPose cameraPose(CameraMode mode, const vehicle::BodyPose& chassis, const OrbitState& orbit,
                      double chaseHeading = std::numeric_limits<double>::quiet_NaN());

}  // namespace bdfcar::render
