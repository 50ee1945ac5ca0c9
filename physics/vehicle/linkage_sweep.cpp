#include "vehicle/linkage_sweep.h"

#include <Eigen/QR>
#include <string>

#include "multibody/constraints.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "multibody/multibody_dae.h"
#include "vehicle/equilibrium.h"

namespace bdfcar::vehicle {

using Eigen::VectorXd;

LinkageSweep::LinkageSweep(const Vehicle& v) : v_(v), m_(v.model), d_(mb::makeData(v.model)) {
  for (const mb::CutJoint& c : m_.cutJoints)
    if (c.type != mb::CutJointType::Driver)
      for (int r = 0; r < c.rows; ++r) rows_.push_back(c.row + r);
  for (size_t i = 0; i < m_.bodies.size(); ++i) {
    const int b = static_cast<int>(i);
    bool spin = false;
    for (const WheelLayout& w : v.layout.wheels) spin |= w.spindle == b;
    if (b == v.layout.chassis || b == v.layout.rack || b == v.layout.engine || spin) continue;
    for (int k = 0; k < m_.bodies[i].nv; ++k) free_.push_back(m_.bodies[i].vIndex + k);
  }
  if (static_cast<int>(free_.size()) != static_cast<int>(rows_.size()) + 4)
    throw mb::ModelError("kinematic model: the suspension has " + std::to_string(free_.size()) +
                         " coordinates and " + std::to_string(rows_.size()) +
                         " loop equations; a sweep by wheel travel needs exactly one free motion per wheel");
  design_ = designPositions(v);
  std::string msg;
  mb::MultibodyDae dae(m_);
  const VectorXd drawn = design_;
  if (!assemble(v, dae, 0.0, design_, msg)) throw mb::ModelError("kinematic model: the linkage does not assemble: " + msg);
  if (const auto far = farFromDesign(v, drawn, design_)) throw mb::ModelError(*far);
  mb::updatePositions(m_, design_, d_);
  for (int w = 0; w < 4; ++w) z0_[w] = wheelCentre(w).z();
}

bool LinkageSweep::solve(const std::array<double, 4>& s, double r, VectorXd& q) {
  q(v_.layout.rackQ) = r;
  VectorXd res(rows()), dx;
  for (int it = 0; it < 25; ++it) {
    residual(q, s, res);
    if (!res.allFinite()) return false;
    if (res.lpNorm<Eigen::Infinity>() < 1e-12) return true;
    if (it % 4 == 0) {
      jacobian(q, s);
      lu_.compute(J_);
    }
    dx = lu_.solve(res);
    step(q, -dx, q);
  }
  residual(q, s, res);
  return res.lpNorm<Eigen::Infinity>() < 1e-10;
}

VectorXd LinkageSweep::travelDirection(const VectorXd& q, int w) {
  jacobian(q, {});
  VectorXd e = VectorXd::Zero(rows());
  e(static_cast<int>(rows_.size()) + w) = 1.0;
  const VectorXd dx = J_.colPivHouseholderQr().solve(e);
  VectorXd full = VectorXd::Zero(m_.nv);
  for (size_t j = 0; j < free_.size(); ++j) full(free_[j]) = dx(j);
  return full;
}

mb::Data& LinkageSweep::at(const VectorXd& q) {
  mb::updatePositions(m_, q, d_);
  return d_;
}

Vec3 LinkageSweep::wheelCentre(int w) const {
  const int sp = v_.layout.wheels[w].spindle;
  const int ch = v_.layout.chassis;
  return d_.R[ch].transpose() * (mb::pointPosition(d_, sp, m_.bodies[sp].inChild.origin) - d_.p[ch]);
}

void LinkageSweep::residual(const VectorXd& q, const std::array<double, 4>& s, VectorXd& out) {
  mb::updatePositions(m_, q, d_);
  mb::constraintPositions(m_, q, d_);
  for (size_t k = 0; k < rows_.size(); ++k) out(k) = d_.phi(rows_[k]);
  for (int w = 0; w < 4; ++w) out(static_cast<int>(rows_.size()) + w) = wheelCentre(w).z() - z0_[w] - s[w];
}

void LinkageSweep::step(const VectorXd& q, const VectorXd& dx, VectorXd& out) {
  VectorXd full = VectorXd::Zero(m_.nv);
  for (size_t j = 0; j < free_.size(); ++j) full(free_[j]) = dx(j);
  VectorXd next(m_.nq);
  mb::retract(m_, q, full, next);
  out = next;
}

// Central differences over the suspension coordinates.
void LinkageSweep::jacobian(const VectorXd& q, const std::array<double, 4>& s) {
  const int n = rows();
  J_.resize(n, static_cast<int>(free_.size()));
  VectorXd rp(n), rm(n), qp(m_.nq), qm(m_.nq), e = VectorXd::Zero(static_cast<int>(free_.size()));
  const double h = 1e-7;
  for (size_t j = 0; j < free_.size(); ++j) {
    e.setZero();
    e(j) = h;
    step(q, e, qp);
    step(q, -e, qm);
    residual(qp, s, rp);
    residual(qm, s, rm);
    J_.col(j) = (rp - rm) / (2 * h);
  }
}

}  // namespace bdfcar::vehicle
