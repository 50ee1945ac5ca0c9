// A vehicle's state mapped between two rungs of the fidelity ladder derived
// from the same linkage, for a switch in mid-run (`[fidelity] suspension =
// "auto"`): the kinematic model and the planar model share the sprung body
// (the same frame), the rack, the carriers' rack travel and the wheels.
//
//  kinematic -> planar: the base takes the sprung body's heading and the
//    roll-axis point's horizontal position; roll and pitch are the sprung
//    body's attitude relative to it (angular velocity split exactly over the
//    yaw, roll and pitch axes); heave and the suspension travels are dropped.
//  planar -> kinematic: the chassis takes the sprung body's pose and
//    velocity; each corner's travel is its static travel less the
//    suspension's share of the corner spring's deflection (the tyre takes
//    the rest), and likewise its rate.
// Rack, rack travel of the steered corners and wheel spins carry over.
#pragma once

#include <Eigen/Core>

#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

void kinematicToPlanar(const Vehicle& kinematic, const Vehicle& planar, const Eigen::VectorXd& qk,
                       const Eigen::VectorXd& vk, Eigen::VectorXd& qp, Eigen::VectorXd& vp);

void planarToKinematic(const Vehicle& planar, const Vehicle& kinematic, const Eigen::VectorXd& qp,
                       const Eigen::VectorXd& vp, Eigen::VectorXd& qk, Eigen::VectorXd& vk);

}  // namespace bdfcar::vehicle
