// Cut-joint constraints at the three levels of the over-determined DAE
// (paper eqs. 3.1-3.3): Phi(q) = 0, Phi_q v + Phi_t = 0,
// Phi_q a + (Phi_q v)_q v + Phi_tt = 0, their Jacobian Phi_q, and the
// generalized constraint forces Phi_q^T lambda.
#pragma once

#include "multibody/data.h"

namespace bdfcar::mb {

// Samples every driver signal at time t into data.driverTargets.
void sampleDrivers(const Model& model, Data& data, double t);

// phi, phiDot, phiDDot for the current positions, velocities and
// accelerations (and the sampled driver targets).
void constraintResiduals(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                         const Eigen::VectorXd& a, Data& data);

// Position-level residual only (needs updatePositions; for assembly).
void constraintPositions(const Model& model, const Eigen::VectorXd& q, Data& data);

// Subtracts the cut-joint reaction wrenches of lambda from fext so that the
// backward pass yields tau + Phi_q^T lambda (spherical and distance joints).
void applyConstraintWrenches(const Model& model, const Eigen::VectorXd& lambda, Data& data);
// Adds the driver rows of Phi_q^T lambda to tau (after inverseDynamics).
void addDriverReactions(const Model& model, const Eigen::VectorXd& lambda, Data& data);

// Phi_q (nc x nv) at the current positions, derivative with respect to the
// tangent increments used by retract().
void constraintJacobian(const Model& model, const Data& data, Eigen::MatrixXd& Phi_q);

}  // namespace bdfcar::mb
