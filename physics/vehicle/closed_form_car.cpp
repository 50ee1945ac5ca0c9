#include "vehicle/closed_form_car.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "integrator/all_finite.h"
#include "multibody/joint.h"
#include "multibody/model_error.h"

namespace bdfcar::vehicle {

ClosedFormCar::ClosedFormCar(const Vehicle& v, const terrain::Terrain& terrain, const TerrainContactOptions& options)
    : vehicle_(v), forces_(v, terrain, options) {
  const mb::Model& m = v.model;
  for (const mb::CutJoint& c : m.cutJoints) {
    if (c.type != mb::CutJointType::Driver) continue;  // a derived class refuses loops it does not carry
    const mb::Body& b = m.bodies[c.drivenBody];
    drivenCoordinates_.emplace_back(b.qIndex + c.drivenCoordinate, b.vIndex + c.drivenCoordinate);
  }
}

ClosedFormCar::SpinJoint ClosedFormCar::spinJoint(const mb::Body& b, const std::string& name, const std::string& model) {
  if (b.joint != mb::JointType::Revolute) throw mb::ModelError(model + ": " + name + " does not spin on a revolute joint");
  const Vec3 axis = b.inChild.axes.col(2);  // the spin joint's axis, wheel frame
  const Mat3 I = fullInertia(b);
  SpinJoint out;
  out.inertia = axis.dot(I * axis);
  const double scale = std::max(1.0, I.norm());
  auto offAxis = [&](const Vec3& x) { return (x - x.dot(axis) * axis).norm(); };
  const Mat3 across = Mat3::Identity() - axis * axis.transpose();
  const double transverse = 0.5 * (I.trace() - out.inertia);
  if ((I * axis - out.inertia * axis).norm() > 1e-9 * scale || offAxis(b.com) > 1e-9 ||
      offAxis(b.inChild.origin) > 1e-9 || std::abs(std::abs(axis.y()) - 1.0) > 1e-9 ||
      (across * I * across - transverse * across).norm() > kTransverseSpread * transverse)
    throw mb::ModelError(model + ": " + name + " is not symmetric about its spin axis (its y axis)");
  out.sign = axis.y() > 0 ? 1.0 : -1.0;
  out.symmetric = transverse * across + out.inertia * axis * axis.transpose();
  return out;
}

void ClosedFormCar::fastColumnParts(double t, integ::Mat& parts) {
  const int m = static_cast<int>(fastColumns_.size());
  parts.setZero(n_, m);
  const double h = forces_.sinceAccepted(t);
  const VehicleForces::DrivelineTorques T0 = drivelineNow(h);
  for (int c = 0; c < m; ++c) {
    const int w = c;  // fastColumns_: the spins in wheel order
    const double dv = VehicleForces::spinIncrement(kinematics_[w].spinRate);
    addSpinChange(w, dv, dv, h, T0, parts.col(c));
  }
}

bool ClosedFormCar::fastRowChange(double t, int k, double dv, double& change) {
  const double h = forces_.sinceAccepted(t);
  rowScratch_.setZero(n_);
  addSpinChange(k, dv, 1.0, h, drivelineNow(h), rowScratch_);
  change = rowScratch_(fastColumns_[k]);
  return true;
}

VehicleForces::DrivelineTorques ClosedFormCar::drivelineNow(double h) const {
  return engineV() >= 0 ? forces_.drivelineAt(engineSpeed_, relativeSpin_, h) : VehicleForces::DrivelineTorques{};
}

// The change of F by wheel w's tyre, brake and driveline when its spin's
// joint rate moves by dv, divided by per (dv: the column's slope; 1: the
// change itself).
void ClosedFormCar::addSpinChange(int w, double dv, double per, double h, const VehicleForces::DrivelineTorques& T0,
                                  Eigen::Ref<integ::Vec> col) const {
  const double sign = spinSign(w);
  tyre::WheelKinematics k = kinematics_[w];
  k.spinRate += sign * dv;  // the joint rate moves the wheel's spin about its y by sign
  addTyreForces(w, forces_.tyreAt(w, k, h), 1.0 / per, col);
  addTyreForces(w, forces_.outputs()[w].out, -1.0 / per, col);
  const double spin = relativeSpin_[w];
  col(spinV(w)) -= sign * (forces_.brakeTorque(w, spin + sign * dv, h) - forces_.brakeTorque(w, spin, h)) / per;
  if (engineV() < 0) return;
  const std::vector<int>& driven = forces_.drivenWheels();
  if (std::find(driven.begin(), driven.end(), w) == driven.end()) return;
  std::array<double, 4> moved = relativeSpin_;
  moved[w] += sign * dv;
  const VehicleForces::DrivelineTorques T1 = forces_.drivelineAt(engineSpeed_, moved, h);
  col(engineV()) -= ((T1.engine - T1.clutch) - (T0.engine - T0.clutch)) / per;
  for (int u : driven) addDriveTorque(u, (T1.drive[u] - T0.drive[u]) / per, col);
}

integ::EvalStatus ClosedFormCar::residual(double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& a,
                                          const integ::Vec&, integ::Residual& out, bool, integ::Message& msg) {
  equationsOf(t, q.data(), v.data(), a, out.F.data());
  if (!integ::allFinite(out.F)) {
    msg.set("non-finite equations of motion at t = %.6g s", t);
    return integ::EvalStatus::Recoverable;
  }
  return integ::EvalStatus::Ok;
}

bool ClosedFormCar::stateJacobian(double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& a,
                                  integ::Mat& Fq, integ::Mat& Fv) {
  constexpr int kMaxV = 16, kMaxQ = kMaxV + 1;
  if (n_ > kMaxV || nq_ > kMaxQ) return false;
  // The directions: the positions' tangent increments (their columns of
  // F_q) but those the equations do not read (the wheels' and the crank's
  // angles: their columns are zero), then the velocities (F_v); as many
  // per evaluation as a Dual carries.
  std::array<int, 2 * kMaxV> direction{};
  int count = 0;
  for (int j = 0; j < n_; ++j)
    if (!angleOnly(j)) direction[count++] = j;
  for (int j = 0; j < n_; ++j) direction[count++] = n_ + j;
  Fq.setZero(n_, n_);
  Fv.setZero(n_, n_);
  // The retraction's tangent at dq = 0 for the chassis' joint: the
  // derivative of its position coordinate i along tangent direction j
  // (mb::jointRetract); the other coordinates are plain (q_i + dq_i).
  Eigen::Matrix<double, 7, 6> chassis = Eigen::Matrix<double, 7, 6>::Zero();
  if (chassisJoint_ == mb::JointType::Planar) {
    // (x, y) + Rz(yaw) dq_xy, yaw + dq_yaw.
    const pm::SinCos& r = baseHeading(q(2));
    chassis.topLeftCorner<3, 3>() << r.c, -r.s, 0, r.s, r.c, 0, 0, 0, 1;
  } else {
    // The free joint: p + R dq_lin; the quaternion (w, u) times exp(dq_ang),
    // to first order (w, u) (1, dq_ang / 2): along e_k, dw = -u_k / 2,
    // du = (w e_k + u x e_k) / 2.
    chassis.topLeftCorner<3, 3>() = mb::quatToMatrix(q.data() + 3);
    const double w = q(3);
    const Vec3 u(q(4), q(5), q(6));
    for (int k = 0; k < 3; ++k) {
      chassis(3, 3 + k) = -0.5 * u(k);
      chassis.block<3, 1>(4, 3 + k) = 0.5 * (w * Vec3::Unit(k) + u.cross(Vec3::Unit(k)));
    }
  }
  std::array<ad::Dual, kMaxQ> qd;
  std::array<ad::Dual, kMaxV> vd, F;
  for (int first = 0; first < count; first += ad::kDirections) {
    const int last = std::min(count, first + ad::kDirections);
    for (int i = 0; i < nq_; ++i) qd[i] = ad::Dual(q(i));
    for (int j = 0; j < n_; ++j) vd[j] = ad::Dual(v(j));
    for (int d = first; d < last; ++d) {
      const int j = direction[d];
      if (j >= n_) {
        vd[j - n_].der[d - first] = 1.0;
        continue;
      }
      if (j < chassisV_)
        for (int i = 0; i < chassisQ_; ++i) qd[i].der[d - first] = chassis(i, j);
      else
        qd[j - chassisV_ + chassisQ_].der[d - first] = 1.0;
    }
    for (int j = 0; j < n_; ++j) F[j] = ad::Dual(0.0);
    if (!dualEquations(t, qd.data(), vd.data(), a, F.data())) return false;
    for (int d = first; d < last; ++d) {
      const int j = direction[d];
      for (int i = 0; i < n_; ++i) (j < n_ ? Fq(i, j) : Fv(i, j - n_)) = F[i].der[d - first];
    }
  }
  return true;
}

template <typename T>
ClosedFormCar::DriveTorques<T> ClosedFormCar::driveTorques(const T& engineSpeed, const std::array<T, 4>& spins,
                                                           double h) {
  DriveTorques<T> out;
  const bool engine = engineV() >= 0;
  if constexpr (std::is_same_v<T, double>) {
    engineSpeed_ = engine ? engineSpeed : 0.0;
    if (engine) out.crank = forces_.drivelineTorques(engineSpeed_, spins, h);
    for (int w = 0; w < 4; ++w) out.wheel[w] = forces_.wheels()[w].driveTorque;
  } else {
    for (int w = 0; w < 4; ++w) out.wheel[w] = T(forces_.wheels()[w].driveTorque);
    if (engine) {
      const VehicleForces::DrivelineTorquesT<T> D = forces_.drivelineAt(engineSpeed, spins, h);
      out.crank = D.engine - D.clutch;
      for (int w : forces_.drivenWheels()) out.wheel[w] = D.drive[w];
    }
  }
  return out;
}

template ClosedFormCar::DriveTorques<double> ClosedFormCar::driveTorques(const double&, const std::array<double, 4>&,
                                                                         double);
template ClosedFormCar::DriveTorques<ad::Dual> ClosedFormCar::driveTorques(const ad::Dual&,
                                                                           const std::array<ad::Dual, 4>&, double);

const pm::SinCos& ClosedFormCar::baseHeading(double yaw) const {
  const auto bits = std::bit_cast<std::uint64_t>(yaw);
  if (!headingKnown_ || bits != headingAngleBits_) {
    heading_ = pm::sincos(yaw);
    headingAngleBits_ = bits;
    headingKnown_ = true;
  }
  return heading_;
}

void ClosedFormCar::retract(const integ::Vec& q, const integ::Vec& dq, integ::Vec& out) const {
  if (chassisJoint_ == mb::JointType::Planar) {
    const pm::SinCos& r = baseHeading(q(2));
    mb::planarRetract(q.data(), dq.data(), r.s, r.c, out.data());
  } else {
    mb::jointRetract(chassisJoint_, q.data(), dq.data(), out.data());
  }
  // The rest, plain coordinates: a loop (an Eigen tail expression's set-up
  // costs more than its handful of additions).
  for (int i = chassisQ_, j = chassisV_; i < nq_; ++i, ++j) out(i) = q(i) + dq(j);
}

void ClosedFormCar::localCoordinates(const integ::Vec& base, const integ::Vec& q, integ::Vec& out) const {
  if (chassisJoint_ == mb::JointType::Planar) {
    const pm::SinCos& r = baseHeading(base(2));
    mb::planarLocal(base.data(), q.data(), r.s, r.c, out.data());
  } else {
    mb::jointLocal(chassisJoint_, base.data(), q.data(), out.data());
  }
  for (int i = chassisQ_, j = chassisV_; i < nq_; ++i, ++j) out(j) = q(i) - base(i);
}

void ClosedFormCar::localRate(const integ::Vec& delta, const integ::Vec& v, integ::Vec& out) const {
  mb::jointLocalRate(chassisJoint_, delta.data(), v.data(), out.data());
  for (int i = chassisV_; i < n_; ++i) out(i) = v(i);
}

mb::SignalValue ClosedFormCar::rackInStep(double t) const {
  mb::SignalValue rack = rack_ ? rack_->at(t) : mb::SignalValue{};
  const double h = forces_.sinceAccepted(t);
  if (rack_ && h > 0) rack.accel = (rack.rate - rack_->at(t - h).rate) / h;
  return rack;
}

void ClosedFormCar::driveMultibody(double t, integ::Vec& qm, integ::Vec& vm) const {
  const mb::SignalValue rack = rack_ ? rack_->at(t) : mb::SignalValue{};
  for (const auto& [iq, iv] : drivenCoordinates_) {
    qm(iq) = rack.value;
    vm(iv) = rack.rate;
  }
}

integ::SolutionPoint ClosedFormCar::multibodyPoint(const integ::SolutionPoint& p, mb::MultibodyDae& view) {
  const mb::Model& m = vehicle_.model;
  integ::SolutionPoint out;
  out.t = p.t;
  toMultibody(p.t, p.q, p.v, out.q, out.v);
  integ::Vec unusedQ;
  toMultibody(p.t, p.q, p.a, unusedQ, out.a);  // the accelerations map as the velocities do, but for the rack's
  const mb::SignalValue rack = rack_ ? rack_->at(p.t) : mb::SignalValue{};
  for (const auto& driven : drivenCoordinates_) out.a(driven.second) = rack.accel;
  // F = tau - joint forces, tau holding each driver's multiplier on its
  // coordinate: with none, the residual there is minus the multiplier.
  out.lambda = integ::Vec::Zero(m.nc);
  integ::Residual r;
  r.resize(view.sizes());
  integ::Message msg;
  if (view.residual(p.t, out.q, out.v, out.a, out.lambda, r, false, msg) == integ::EvalStatus::Ok)
    for (const mb::CutJoint& c : m.cutJoints)
      out.lambda(c.row) = -r.F(m.bodies[c.drivenBody].vIndex + c.drivenCoordinate);
  return out;
}

integ::EvalStatus ClosedFormCar::acceptWheels(double t, double h, const integ::Vec& q, const integ::Vec& v,
                                              integ::Message& msg) {
  if (!integ::allFinite(q) || !integ::allFinite(v)) {
    msg.set("non-finite state at t = %.6g s", t);
    return integ::EvalStatus::Fatal;
  }
  for (int i = 0; i < n_; ++i)
    if (std::abs(v(i)) > limits_.maxVelocity) {
      msg.set("velocity coordinate %d = %.3g exceeds %.3g at t = %.6g s", i, v(i), limits_.maxVelocity, t);
      return integ::EvalStatus::Fatal;
    }
  const double since = forces_.sinceAccepted(t);
  for (int w = 0; w < 4; ++w) forces_.acceptWheel(w, kinematics_[w], relativeSpin_[w], since, h);
  if (engineV() >= 0) forces_.acceptDriveline(v(engineV()), relativeSpin_, since);
  forces_.markAccepted(t, h);
  return integ::EvalStatus::Ok;
}

}  // namespace bdfcar::vehicle
