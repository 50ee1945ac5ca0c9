#include "multibody/data.h"

namespace bdfcar::mb {

Data makeData(const Model& model) {
  const size_t nb = model.bodies.size();
  Data d;
  d.driverSignals.assign(model.nDrivers, nullptr);
  d.Xup.resize(nb);
  d.R.assign(nb, Mat3::Identity());
  d.p.assign(nb, Vec3::Zero());
  d.S = model.S;
  d.vel.assign(nb, Vec6::Zero());
  d.bias.assign(nb, Vec6::Zero());
  d.acc.assign(nb, Vec6::Zero());
  d.fext.assign(nb, Vec6::Zero());
  d.f.assign(nb, Vec6::Zero());
  d.jointForce = Eigen::VectorXd::Zero(model.nv);
  d.tau = Eigen::VectorXd::Zero(model.nv);
  d.phi = Eigen::VectorXd::Zero(model.nc);
  d.phiDot = Eigen::VectorXd::Zero(model.nc);
  d.phiDDot = Eigen::VectorXd::Zero(model.nc);
  d.driverTargets.assign(model.nDrivers, DriverTarget{});
  d.Ic.assign(nb, Mat6::Zero());
  d.springLength.assign(model.springs.size(), 0.0);
  d.springForce.assign(model.springs.size(), 0.0);
  return d;
}

Vec3 pointPosition(const Data& d, int body, const Vec3& s) {
  if (body < 0) return s;
  return d.p[body] + d.R[body] * s;
}

Vec3 pointVelocity(const Data& d, int body, const Vec3& s) {
  if (body < 0) return Vec3::Zero();
  const Vec6& v = d.vel[body];
  return d.R[body] * (v.head<3>() + v.tail<3>().cross(s));
}

Vec3 pointAcceleration(const Data& d, int body, const Vec3& s) {
  if (body < 0) return Vec3::Zero();
  const Vec6& v = d.vel[body];
  const Vec6& a = d.acc[body];
  const Vec3 w = v.tail<3>();
  const Vec3 vp = v.head<3>() + w.cross(s);
  return d.R[body] * (a.head<3>() + a.tail<3>().cross(s) + w.cross(vp));
}

Vec3 angularVelocity(const Data& d, int body) {
  if (body < 0) return Vec3::Zero();
  return d.R[body] * d.vel[body].tail<3>();
}

void addWorldWrench(Data& d, int body, const Vec3& point, const Vec3& force, const Vec3& torque) {
  if (body < 0) return;
  const Mat3& R = d.R[body];
  const Vec3 fb = R.transpose() * force;
  const Vec3 sb = R.transpose() * (point - d.p[body]);
  d.fext[body].head<3>() += fb;
  d.fext[body].tail<3>() += sb.cross(fb) + R.transpose() * torque;
}

}  // namespace bdfcar::mb
