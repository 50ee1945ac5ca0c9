#include "multibody/multibody_dae.h"

#include <cmath>


#include "integrator/all_finite.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/kinematics.h"

namespace bdfcar::mb {

MultibodyDae::MultibodyDae(const Model& model) : model_(model), data_(makeData(model)) {
  zeroV_.setZero(model.nv);
}

void MultibodyDae::retract(const integ::Vec& q, const integ::Vec& dq, integ::Vec& out) const {
  mb::retract(model_, q, dq, out);
}

void MultibodyDae::localCoordinates(const integ::Vec& base, const integ::Vec& q, integ::Vec& out) const {
  mb::localCoordinates(model_, base, q, out);
}

void MultibodyDae::localRate(const integ::Vec& delta, const integ::Vec& v, integ::Vec& out) const {
  mb::localRate(model_, delta, v, out);
}

void MultibodyDae::applyForces(double t) {
  clearForces(model_, data_);
  data_.jointForce.setZero();
  applyGravity(model_, data_);
  applySprings(model_, data_);
  for (ForceProvider* p : providers_) p->apply(model_, data_, t);
}

void MultibodyDae::evaluateKinematics(double t, const integ::Vec& q, const integ::Vec& v) {
  sampleDrivers(model_, data_, t);
  updatePositions(model_, q, data_);
  updateVelocities(model_, v, data_);
  updateAccelerations(model_, zeroV_, data_);
  applyForces(t);
}

void MultibodyDae::beginStep(double t, const integ::Vec& q, const integ::Vec&) {
  bool any = false;
  for (ForceProvider* p : providers_) any |= p->needsBeginStep(t);
  if (!any) return;
  updatePositions(model_, q, data_);
  for (ForceProvider* p : providers_)
    if (p->needsBeginStep(t)) p->beginStep(model_, data_, t);
}

// Force-law states, the next step's preparation and the divergence checks
// (finite, bounded velocities, constraints closed), from the kinematics of the
// last residual evaluation: no extra kinematic pass on the step's path.
integ::EvalStatus MultibodyDae::acceptStep(double t, double h, const integ::Vec& q, const integ::Vec& v,
                                           integ::Message& msg) {
  if (!integ::allFinite(q) || !integ::allFinite(v)) {
    msg.set("non-finite state at t = %.6g s", t);
    return integ::EvalStatus::Fatal;
  }
  for (int i = 0; i < model_.nv; ++i)
    if (std::abs(v(i)) > limits_.maxVelocity) {
      msg.set("velocity coordinate %d = %.3g exceeds %.3g at t = %.6g s", i, v(i), limits_.maxVelocity, t);
      return integ::EvalStatus::Fatal;
    }
  for (ForceProvider* p : providers_) p->acceptStep(model_, data_, t, h);
  for (const CutJoint& c : model_.cutJoints)
    for (int r = 0; r < c.rows; ++r)
      if (!(std::abs(data_.phi(c.row + r)) <= limits_.maxConstraintViolation)) {
        msg.set("constraint '%s' violated by %.3g (limit %.3g) at t = %.6g s", c.name.c_str(), data_.phi(c.row + r),
                limits_.maxConstraintViolation, t);
        return integ::EvalStatus::Fatal;
      }
  return integ::EvalStatus::Ok;
}

integ::EvalStatus MultibodyDae::residual(double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& a,
                                         const integ::Vec& lambda, integ::Residual& out, bool withConstraints,
                                         integ::Message& msg) {
  sampleDrivers(model_, data_, t);
  updatePositions(model_, q, data_);
  updateVelocities(model_, v, data_);
  updateAccelerations(model_, a, data_);
  applyForces(t);
  applyConstraintWrenches(model_, lambda, data_);
  inverseDynamics(model_, data_);
  addDriverReactions(model_, lambda, data_);
  out.F = data_.tau - data_.jointForce;
  if (withConstraints) {
    constraintResiduals(model_, q, v, a, data_);
    out.phi = data_.phi;
    out.phiDot = data_.phiDot;
    out.phiDDot = data_.phiDDot;
  }
  if (!integ::allFinite(out.F)) {
    msg.set("non-finite equations of motion at t = %.6g s", t);
    return integ::EvalStatus::Recoverable;
  }
  return integ::EvalStatus::Ok;
}

bool MultibodyDae::hasFastColumnParts() const {
  if (fastColumns_.empty()) return false;
  for (const ForceProvider* p : providers_)
    if (p->hasFastColumnParts()) return true;
  return false;
}

void MultibodyDae::fastColumnParts(double t, integ::Mat& parts) {
  parts.setZero(model_.nv, static_cast<int>(fastColumns_.size()));
  for (ForceProvider* p : providers_)
    if (p->hasFastColumnParts()) p->addFastColumnParts(model_, data_, t, fastColumns_, parts);
}

bool MultibodyDae::fastRowChange(double t, int k, double dv, double& change) {
  change = 0;
  bool given = false;
  for (ForceProvider* p : providers_)
    if (p->hasFastColumnParts()) given = p->addFastRowChange(model_, data_, t, fastColumns_[k], dv, change) || given;
  return given;
}

bool MultibodyDae::massMatrix(double /*t*/, const integ::Vec& q, integ::Mat& Fa) {
  updatePositions(model_, q, data_);
  mb::massMatrix(model_, data_, Fa);
  return true;
}

bool MultibodyDae::constraintJacobian(double /*t*/, const integ::Vec& q, integ::Mat& Phi_q) {
  updatePositions(model_, q, data_);
  mb::constraintJacobian(model_, data_, Phi_q);
  return true;
}

}  // namespace bdfcar::mb
