// Recursive kinematics along the tree (three loops over the parent array):
// positions -> velocities -> accelerations, in body coordinates, plus world
// poses of every body. The velocity transformation Y = B v of the paper is
// carried implicitly by the parent-to-child transforms and motion subspaces.
#pragma once

#include "multibody/data.h"

namespace bdfcar::mb {

// Xup, world poses R/p and motion subspaces S for positions q (nq).
void updatePositions(const Model& model, const Eigen::VectorXd& q, Data& data);
// Spatial velocities and velocity-product accelerations for velocities v (nv);
// needs updatePositions (the subspaces and the joint angles' sines and cosines).
void updateVelocities(const Model& model, const Eigen::VectorXd& v, Data& data);
// Spatial accelerations for joint accelerations a (nv); needs updateVelocities.
void updateAccelerations(const Model& model, const Eigen::VectorXd& a, Data& data);

// q (+) dq over the whole tree (dq has size nv).
void retract(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& dq, Eigen::VectorXd& out);
// Local coordinates of q around base (size nv).
void localCoordinates(const Model& model, const Eigen::VectorXd& base, const Eigen::VectorXd& q,
                      Eigen::VectorXd& out);
// Rate of the local coordinates delta for joint velocities v (size nv).
void localRate(const Model& model, const Eigen::VectorXd& delta, const Eigen::VectorXd& v, Eigen::VectorXd& out);

}  // namespace bdfcar::mb
