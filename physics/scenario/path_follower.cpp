#include "scenario/path_follower.h"

#include <algorithm>
#include <cmath>
#include "portable_math.h"

namespace bdfcar::scenario {

double PathFollower::steer(double x, double y, double yaw, double v, double yawRate, double dt) {
  // Learn the understeer from how much curvature the last command produced,
  // only while turning clearly (small curvatures say nothing).
  const double obtained = std::abs(v) > 1.0 ? yawRate / v : 0.0;
  if (std::abs(s_.lastCurvature) > 2e-3 && std::abs(obtained) > 1e-3 && s_.lastCurvature * obtained > 0) {
    const double ratio = std::clamp(s_.lastCurvature / obtained, 0.5, 4.0);
    const double a = std::clamp(dt / p_.learningTime, 0.0, 1.0);
    s_.gain += a * (ratio - s_.gain);
  }
  const double L = std::max(p_.minLookAhead, p_.lookAheadTime * std::abs(v));
  // The target on the path L ahead (driver_paths.h).
  const Eigen::Vector2d target = target_(x, y, yaw, L);
  const double tx = target.x(), ty = target.y();
  // Pure pursuit: curvature 2 sin(eta) / L with eta the angle to the target in the vehicle frame.
  const double dx = tx - x, dy = ty - y;
  const double eta = pm::atan2(dy, dx) - yaw;
  const double curvature = 2.0 * pm::sin(eta) / pm::hypot(dx, dy);
  s_.lastCurvature = curvature;
  const double roadWheel = pm::atan(p_.wheelbase * curvature * s_.gain);
  return std::clamp(roadWheel * p_.steerPerRoadWheel, -1.0, 1.0);
}

}  // namespace bdfcar::scenario
