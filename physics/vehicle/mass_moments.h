// Mass, first moment and inertia about a frame's origin of a set of rigid
// bodies expressed in that frame: sums (and differences) of rigid bodies, as
// the reduced models lump and split the linkage's bodies.
#pragma once

#include "multibody/spatial.h"

namespace bdfcar::vehicle {

struct MassMoments {
  double m = 0;
  mb::Vec3 h = mb::Vec3::Zero();
  mb::Mat3 I = mb::Mat3::Zero();
  void add(double mass, const mb::Vec3& com, const mb::Mat3& inertiaAtCom, double sign = 1.0) {
    m += sign * mass;
    h += sign * mass * com;
    I += sign * (inertiaAtCom + mass * (com.squaredNorm() * mb::Mat3::Identity() - com * com.transpose()));
  }
  mb::Vec3 com() const { return h / m; }
  mb::Mat3 inertiaAtCom() const {
    const mb::Vec3 c = com();
    mb::Mat3 J = I - m * (c.squaredNorm() * mb::Mat3::Identity() - c * c.transpose());
    return 0.5 * (J + J.transpose());
  }
};

}  // namespace bdfcar::vehicle
