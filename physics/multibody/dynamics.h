// Joint-space dynamics: the recursive Newton-Euler residual of paper eq. 2.3
// (F = B^T (M Ydot - Q) + Phi_q^T lambda, computed in O(n) without forming B),
// the joint-space mass matrix F_a = B^T M B (composite rigid body algorithm),
// and the applied forces (gravity, spring-dampers).
#pragma once

#include "multibody/data.h"

namespace bdfcar::mb {

// Clears the applied wrenches.
void clearForces(const Model& model, Data& data);
// Adds gravity m g at every centre of mass. Needs positions.
void applyGravity(const Model& model, Data& data);
// Adds spring-damper forces. Needs positions and velocities.
void applySprings(const Model& model, Data& data);
// Backward pass: tau = S^T f with f = I a + v x* I v - fext (Featherstone RNEA).
// Needs accelerations and the applied (and constraint) wrenches in fext.
void inverseDynamics(const Model& model, Data& data);
// The joint forces that a spatial force f (body coordinates) on `body` alone
// balances, times `scale`, added to out (nv): inverseDynamics' S^T X^T f
// along the path to the root, without a pass over the tree. Needs positions.
void addPathJointForces(const Model& model, const Data& data, int body, Vec6 f, double scale,
                        Eigen::Ref<Eigen::VectorXd> out);
// Joint-space mass matrix (nv x nv). Needs positions.
void massMatrix(const Model& model, Data& data, Eigen::MatrixXd& M);

// Total kinetic energy. Needs velocities.
double kineticEnergy(const Model& model, const Data& data);
// Gravitational potential energy (zero at the world origin). Needs positions.
double potentialEnergy(const Model& model, const Data& data);

}  // namespace bdfcar::mb
