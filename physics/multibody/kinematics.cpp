#include "multibody/kinematics.h"

#include <cmath>

#include "multibody/joint.h"

namespace bdfcar::mb {

namespace {

// Motion (lin; ang) at the child joint frame origin in joint-frame axes,
// expressed at the body origin in body axes.
Vec6 jointToBody(const Body& b, const Vec6& m) {
  const Mat3& Cc = b.inChild.axes;
  Vec6 out;
  out.tail<3>().noalias() = Cc * m.tail<3>();
  out.head<3>().noalias() = Cc * m.head<3>();
  out.head<3>() += b.inChild.origin.cross(out.tail<3>());
  return out;
}

// Rotation about the joint axis by angle t from the rest orientation.
Mat3 rotateAboutAxis(const Body& b, double t) {
  const double s = std::sin(t), c = std::cos(t);
  return b.restRotation + s * b.rodrigues1 + (1.0 - c) * b.rodrigues2;
}

// Child axes in parent coordinates for a joint rotation Rj between the joint frames.
Mat3 throughJointFrames(const Body& b, const Mat3& Rj) {
  if (b.identityAxes) return Rj;
  return b.inParent.axes * Rj * b.inChild.axes.transpose();
}

// Joint velocity (or acceleration) mapped to a body-coordinate motion: S qdot.
Vec6 subspaceTimes(const Data& d, const Body& b, const Eigen::VectorXd& x) {
  Vec6 out = d.S.col(b.vIndex) * x(b.vIndex);
  for (int k = 1; k < b.nv; ++k) out += d.S.col(b.vIndex + k) * x(b.vIndex + k);
  return out;
}

}  // namespace

void updatePositions(const Model& model, const Eigen::VectorXd& q, Data& d) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    const double* qi = q.data() + b.qIndex;
    Mat3 R = b.restRotation;
    Vec3 t = b.inParent.origin;
    switch (b.joint) {
      case JointType::Revolute: R = rotateAboutAxis(b, qi[0]); break;
      case JointType::Prismatic:
        R = b.restRotation;
        t += b.axisInParent * qi[0];
        break;
      case JointType::Cylindrical:
        R = rotateAboutAxis(b, qi[0]);
        t += b.axisInParent * qi[1];
        break;
      case JointType::Universal: {
        R = throughJointFrames(b, rotX(qi[0]) * rotY(qi[1]));
        SubspaceBlock Sj;
        jointSubspace(b.joint, qi, Sj);
        d.S.col(b.vIndex) = jointToBody(b, Sj.col(0));
        break;
      }
      case JointType::Spherical: R = throughJointFrames(b, quatToMatrix(qi)); break;
      case JointType::Free:
        R = throughJointFrames(b, quatToMatrix(qi + 3));
        t += b.inParent.axes * Vec3(qi[0], qi[1], qi[2]);
        break;
    }
    t.noalias() -= R * b.inChild.origin;
    Transform& X = d.Xup[i];
    X.E = R.transpose();
    X.r = t;
    if (b.parent < 0) {
      d.R[i] = R;
      d.p[i] = t;
    } else {
      d.R[i].noalias() = d.R[b.parent] * R;
      d.p[i] = d.p[b.parent];
      d.p[i].noalias() += d.R[b.parent] * t;
    }
  }
}

void updateVelocities(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Data& d) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    const Vec6 vJ = subspaceTimes(d, b, v);
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
    Vec6 acc = subspaceTimes(d, b, a) + d.bias[i];
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
