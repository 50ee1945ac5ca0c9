// Where each camera mode puts the eye, from the chassis pose alone (no OSG):
// chase (behind, yaw only), hood (rigid on the car), orbit (around the car),
// top-down (world x to the right).
#pragma once

#include <Eigen/Core>

#include "render/scene.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::render {

struct CameraPose {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::UnitX(), up = Eigen::Vector3d::UnitZ();
  double fovYDeg = 45.0;  // vertical field of view
  double zNear = 0.25, zFar = 2500.0;
};

struct OrbitState {
  double yaw = 2.4;        // rad, around the car, relative to its heading (pi = from behind)
  double pitch = 0.32;     // rad above the horizon
  double distance = 8.5;   // m from the car
};

// Heading angle of the chassis x axis projected on the ground plane, rad.
double headingOf(const vehicle::BodyPose& chassis);

// Eye, target and up vector of the camera for this mode and chassis pose.
CameraPose cameraPose(CameraMode mode, const vehicle::BodyPose& chassis, const OrbitState& orbit);

}  // namespace bdfcar::render
