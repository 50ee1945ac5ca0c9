#include "scenario/path_follower.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::scenario {

double PathFollower::steer(double x, double y, double yaw, double v) const {
  const double L = std::max(p_.minLookAhead, p_.lookAheadTime * std::abs(v));
  // Target on the path L ahead along x (the course runs along +x).
  const double tx = x + L * std::cos(yaw), ty = path_(tx);
  // Pure pursuit: curvature 2 sin(eta) / L with eta the angle to the target in the vehicle frame.
  const double dx = tx - x, dy = ty - y;
  const double eta = std::atan2(dy, dx) - yaw;
  const double dist = std::hypot(dx, dy);
  const double curvature = 2.0 * std::sin(eta) / dist;
  const double roadWheel = std::atan(p_.wheelbase * curvature);
  return std::clamp(roadWheel * p_.steerPerRoadWheel, -1.0, 1.0);
}

}  // namespace bdfcar::scenario
