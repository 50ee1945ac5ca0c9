#include "render/camera_rig.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::render {

// Heading of the chassis x axis in the ground plane.
double headingOf(const vehicle::BodyPose& chassis) {
  const Eigen::Vector3d x = chassis.rotation * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x());
}

double ChaseHeading::update(double carHeading, double time) {
  const double dt = time - time_;
  if (!valid_ || dt < 0 || dt > kSnapAfter) {
    valid_ = true;
    heading_ = carHeading;
    rate_ = 0;
    time_ = time;
    return heading_;
  }
  // The spring's exact motion over the frame toward the car's heading held
  // (any frame rate gives the same camera): with x the offset from the car,
  // the short way round, x(t) = (x0 + (v0 + w x0) t) exp(-w t).
  const double w = kOmega, x0 = std::remainder(heading_ - carHeading, 2.0 * M_PI), v0 = rate_;
  const double c = v0 + w * x0, decay = std::exp(-w * dt);
  heading_ = carHeading + (x0 + c * dt) * decay;
  rate_ = (v0 - w * c * dt) * decay;
  time_ = time;
  return heading_;
}

// Camera pose per mode; chase and top-down ignore roll and pitch so the horizon stays level.
CameraPose cameraPose(CameraMode mode, const vehicle::BodyPose& chassis, const OrbitState& orbit, double chaseHeading) {
  const Eigen::Vector3d p = chassis.position;
  const double psi = headingOf(chassis);
  const Eigen::Vector3d forward(std::cos(psi), std::sin(psi), 0.0);
  CameraPose c;
  switch (mode) {
    case CameraMode::Chase: {
      const double h = std::isnan(chaseHeading) ? psi : chaseHeading;
      const Eigen::Vector3d behind(std::cos(h), std::sin(h), 0.0);
      c.eye = p - 7.0 * behind + Eigen::Vector3d(0, 0, 1.9);
      c.centre = p + 3.0 * behind + Eigen::Vector3d(0, 0, 0.3);
      c.fovYDeg = 45.0;
      break;
    }
    case CameraMode::Hood: {
      // Above the hood, rigid with the body (shows pitch and roll); only the
      // front of the hood stays in the picture.
      const Eigen::Matrix3d r = chassis.rotation.toRotationMatrix();
      c.eye = p + r * Eigen::Vector3d(1.2, 0.0, 0.6);
      c.centre = c.eye + r * Eigen::Vector3d(20.0, 0.0, -1.0);
      c.up = r.col(2);
      c.fovYDeg = 55.0;
      c.zNear = 0.05;
      break;
    }
    case CameraMode::Orbit: {
      const double yaw = psi + orbit.yaw, pitch = std::clamp(orbit.pitch, -0.1, 1.5);
      c.centre = p + Eigen::Vector3d(0, 0, 0.2);
      c.eye = c.centre + orbit.distance * Eigen::Vector3d(std::cos(pitch) * std::cos(yaw),
                                                          std::cos(pitch) * std::sin(yaw), std::sin(pitch));
      c.fovYDeg = 40.0;
      break;
    }
    case CameraMode::TopDown:
      c.centre = Eigen::Vector3d(p.x(), p.y(), p.z() - 0.5);
      c.eye = c.centre + Eigen::Vector3d(0, 0, 38.0);
      c.up = Eigen::Vector3d::UnitY();  // world x runs to the right of the picture
      c.fovYDeg = 40.0;
      break;
  }
  return c;
}

}  // namespace bdfcar::render
