#include "multibody/kinematics.h"

#include "multibody/joint.h"

namespace bdfcar::mb {

namespace {

// Motion (lin; ang) given at the child joint frame origin in joint-frame axes,
// expressed at the body origin in body axes.
Vec6 jointToBody(const Body& b, const Vec6& m) {
  const Mat3& Cc = b.inChild.axes;
  Vec6 out;
  out.tail<3>().noalias() = Cc * m.tail<3>();
  out.head<3>().noalias() = Cc * m.head<3>();
  out.head<3>() += b.inChild.origin.cross(out.tail<3>());
  return out;
}

}  // namespace

void updatePositions(const Model& model, const Eigen::VectorXd& q, Data& d) {
  SubspaceBlock Sj;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    Mat3 Rj;
    Vec3 dj;
    jointRelativePose(b.joint, q.data() + b.qIndex, Rj, dj);
    const Mat3 Rpc = b.inParent.axes * Rj * b.inChild.axes.transpose();
    const Vec3 tpc = b.inParent.origin + b.inParent.axes * dj - Rpc * b.inChild.origin;
    Transform& X = d.Xup[i];
    X.E = Rpc.transpose();
    X.r = tpc;
    if (b.parent < 0) {
      d.R[i] = Rpc;
      d.p[i] = tpc;
    } else {
      d.R[i].noalias() = d.R[b.parent] * Rpc;
      d.p[i] = d.p[b.parent] + d.R[b.parent] * tpc;
    }
    jointSubspace(b.joint, q.data() + b.qIndex, Sj);
    for (int k = 0; k < b.nv; ++k) d.S.col(b.vIndex + k) = jointToBody(b, Sj.col(k));
  }
}

void updateVelocities(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Data& d) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    const Vec6 vJ = d.S.middleCols(b.vIndex, b.nv) * v.segment(b.vIndex, b.nv);
    if (b.parent < 0)
      d.vel[i] = vJ;
    else
      d.vel[i] = d.Xup[i].applyMotion(d.vel[b.parent]) + vJ;
    d.bias[i] = crossMotion(d.vel[i], vJ);
    if (b.joint == JointType::Universal)
      d.bias[i] += jointToBody(b, jointSubspaceRateBias(b.joint, q.data() + b.qIndex, v.data() + b.vIndex));
  }
}

void updateAccelerations(const Model& model, const Eigen::VectorXd& a, Data& d) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    Vec6 acc = d.S.middleCols(b.vIndex, b.nv) * a.segment(b.vIndex, b.nv) + d.bias[i];
    if (b.parent >= 0) acc += d.Xup[i].applyMotion(d.acc[b.parent]);
    d.acc[i] = acc;
  }
}

void retract(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& dq, Eigen::VectorXd& out) {
  for (const Body& b : model.bodies)
    jointRetract(b.joint, q.data() + b.qIndex, dq.data() + b.vIndex, out.data() + b.qIndex);
}

void localCoordinates(const Model& model, const Eigen::VectorXd& base, const Eigen::VectorXd& q,
                      Eigen::VectorXd& out) {
  for (const Body& b : model.bodies)
    jointLocal(b.joint, base.data() + b.qIndex, q.data() + b.qIndex, out.data() + b.vIndex);
}

void localRate(const Model& model, const Eigen::VectorXd& delta, const Eigen::VectorXd& v, Eigen::VectorXd& out) {
  for (const Body& b : model.bodies)
    jointLocalRate(b.joint, delta.data() + b.vIndex, v.data() + b.vIndex, out.data() + b.vIndex);
}

}  // namespace bdfcar::mb
