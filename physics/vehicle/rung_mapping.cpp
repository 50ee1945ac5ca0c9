#include "vehicle/rung_mapping.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "multibody/data.h"
#include "multibody/kinematics.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

namespace {

using Eigen::VectorXd;

// What both models share, besides the sprung body: rack, the steered
// corners' rack travel, wheel spins, the engine. `rackTravel(v, w)`: index of corner w's
// rack-travel coordinate, -1 where the corner does not steer.
int rackTravel(const Vehicle& v, int w, bool velocity) {
  const mb::Body& c = v.model.bodies[v.layout.wheels[w].carrier];
  if (c.joint == mb::JointType::Tabulated2) return velocity ? c.vIndex + 1 : c.qIndex + 1;
  if (c.joint == mb::JointType::Tabulated1 && v.planar) return velocity ? c.vIndex : c.qIndex;
  return -1;
}

void copyShared(const Vehicle& from, const Vehicle& to, const VectorXd& qf, const VectorXd& vf, VectorXd& qt,
                VectorXd& vt) {
  qt(to.layout.rackQ) = qf(from.layout.rackQ);
  vt(to.layout.rackV) = vf(from.layout.rackV);
  for (int w = 0; w < 4; ++w) {
    const int qa = rackTravel(from, w, false), qb = rackTravel(to, w, false);
    if (qa >= 0 && qb >= 0) {
      qt(qb) = qf(qa);
      vt(rackTravel(to, w, true)) = vf(rackTravel(from, w, true));
    }
    const mb::Body& sf = from.model.bodies[from.layout.wheels[w].spindle];
    const mb::Body& st = to.model.bodies[to.layout.wheels[w].spindle];
    qt(st.qIndex) = qf(sf.qIndex);
    vt(st.vIndex) = vf(sf.vIndex);
  }
  // The engine turns relative to the sprung body in both.
  if (from.layout.engine >= 0 && to.layout.engine >= 0) {
    qt(to.layout.engineQ) = qf(from.layout.engineQ);
    vt(to.layout.engineV) = vf(from.layout.engineV);
  }
}

}  // namespace

void kinematicToPlanar(const Vehicle& kin, const Vehicle& planar, const VectorXd& qk, const VectorXd& vk,
                       VectorXd& qp, VectorXd& vp) {
  mb::Data d = mb::makeData(kin.model);
  mb::updatePositions(kin.model, qk, d);
  mb::updateVelocities(kin.model, vk, d);
  const int ch = kin.layout.chassis;
  const Mat3 Rc = d.R[ch];
  const mb::Body& sprung = planar.model.bodies[planar.layout.chassis];
  const mb::Body& base = planar.model.bodies[planar.layout.base];
  const Mat3 rest = sprung.inChild.axes.transpose();  // the sprung body's axes in the base's at zero roll and pitch
  // Rc = Rz(psi) Rx(alpha) Ry(beta) rest.
  const Mat3 N = Rc * rest.transpose();
  const double psi = pm::atan2(-N(0, 1), N(1, 1));
  const Mat3 M = mb::rotZ(-psi) * N;
  const double alpha = pm::atan2(M(2, 1), M(1, 1)), beta = pm::atan2(M(0, 2), M(0, 0));
  const Vec3 joint = mb::pointPosition(d, ch, sprung.inChild.origin);
  const Mat3 Rz = mb::rotZ(psi);
  const Vec3 origin = joint - Rz * sprung.inParent.origin;
  qp = mb::neutralPositions(planar.model);
  vp = VectorXd::Zero(planar.model.nv);
  qp(base.qIndex) = origin.x();
  qp(base.qIndex + 1) = origin.y();
  qp(base.qIndex + 2) = psi;
  qp(sprung.qIndex) = alpha;
  qp(sprung.qIndex + 1) = beta;
  // Angular velocity = psi' z + alpha' Rz x + beta' Rz Rx(alpha) y.
  const Vec3 w = mb::angularVelocity(d, ch);
  Mat3 A;
  A.col(0) = Vec3::UnitZ();
  A.col(1) = Rz * Vec3::UnitX();
  A.col(2) = Rz * mb::rotX(alpha) * Vec3::UnitY();
  const Vec3 rates = A.partialPivLu().solve(w);
  const Vec3 vOrigin = mb::pointVelocity(d, ch, sprung.inChild.origin) - rates(0) * Vec3::UnitZ().cross(joint - origin);
  const Vec3 vBase = Rz.transpose() * vOrigin;
  vp(base.vIndex) = vBase.x();
  vp(base.vIndex + 1) = vBase.y();
  vp(base.vIndex + 2) = rates(0);
  vp(sprung.vIndex) = rates(1);
  vp(sprung.vIndex + 1) = rates(2);
  copyShared(kin, planar, qk, vk, qp, vp);
}

void planarToKinematic(const Vehicle& planar, const Vehicle& kin, const VectorXd& qp, const VectorXd& vp,
                       VectorXd& qk, VectorXd& vk) {
  mb::Data d = mb::makeData(planar.model);
  mb::updatePositions(planar.model, qp, d);
  mb::updateVelocities(planar.model, vp, d);
  const PlanarLoads& P = *planar.planar;
  const int sprung = planar.layout.chassis, base = planar.layout.base;
  const mb::Body& ch = kin.model.bodies[kin.layout.chassis];
  qk = mb::neutralPositions(kin.model);
  vk = VectorXd::Zero(kin.model.nv);
  const Eigen::Quaterniond rot(d.R[sprung]);
  qk.segment<3>(ch.qIndex) = d.p[sprung];
  qk(ch.qIndex + 3) = rot.w();
  qk(ch.qIndex + 4) = rot.x();
  qk(ch.qIndex + 5) = rot.y();
  qk(ch.qIndex + 6) = rot.z();
  vk.segment<6>(ch.vIndex) = d.vel[sprung];  // body-frame (linear; angular), as the free joint's
  // Travels: the suspension's share of each corner spring's deflection.
  const Vec3 up = d.R[base].col(2);
  for (int w = 0; w < 4; ++w) {
    const double z = up.dot(mb::pointPosition(d, sprung, P.sprungPoint[w]) - mb::pointPosition(d, base, P.basePoint[w]));
    const double zd =
        up.dot(mb::pointVelocity(d, sprung, P.sprungPoint[w]) - mb::pointVelocity(d, base, P.basePoint[w]));
    const mb::Body& c = kin.model.bodies[kin.layout.wheels[w].carrier];
    qk(c.qIndex) = P.staticTravel[w] - P.suspensionShare[w] * z;
    vk(c.vIndex) = -P.suspensionShare[w] * zd;
  }
  copyShared(planar, kin, qp, vp, qk, vk);
}

}  // namespace bdfcar::vehicle
