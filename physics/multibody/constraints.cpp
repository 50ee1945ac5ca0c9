#include "multibody/constraints.h"

namespace bdfcar::mb {

void sampleDrivers(const Model& model, Data& d, double t) {
  for (int k = 0; k < model.nDrivers; ++k)
    d.driverTargets[k] = d.driverSignals[k] ? d.driverSignals[k]->at(t) : SignalValue{};
}

namespace {

struct PointKinematics {
  Vec3 x, v, a;
};

PointKinematics pointKinematics(const Data& d, int body, const Vec3& s, bool withAcc) {
  PointKinematics k;
  k.x = pointPosition(d, body, s);
  k.v = pointVelocity(d, body, s);
  k.a = withAcc ? pointAcceleration(d, body, s) : Vec3::Zero();
  return k;
}

Vec3 angularAcceleration(const Data& d, int body) {
  if (body < 0) return Vec3::Zero();
  return d.R[body] * d.acc[body].tail<3>();
}

void evaluate(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd* v, const Eigen::VectorXd* a,
              Data& d) {
  const bool withVel = v != nullptr, withAcc = a != nullptr;
  for (const CutJoint& c : model.cutJoints) {
    switch (c.type) {
      case CutJointType::Spherical: {
        const PointKinematics A = pointKinematics(d, c.bodyA, c.pointA, withAcc);
        const PointKinematics B = pointKinematics(d, c.bodyB, c.pointB, withAcc);
        const Mat3 RC = bodyRotation(d, c.frameBody);
        const Vec3 dx = A.x - B.x;
        d.phi.segment<3>(c.row) = RC.transpose() * dx;
        if (!withVel) break;
        const Vec3 w = angularVelocity(d, c.frameBody);
        const Vec3 dv = A.v - B.v;
        d.phiDot.segment<3>(c.row) = RC.transpose() * (dv - w.cross(dx));
        if (!withAcc) break;
        const Vec3 wdot = angularAcceleration(d, c.frameBody);
        const Vec3 da = A.a - B.a;
        d.phiDDot.segment<3>(c.row) =
            RC.transpose() * (da - wdot.cross(dx) - 2.0 * w.cross(dv) + w.cross(w.cross(dx)));
        break;
      }
      case CutJointType::Distance: {
        const PointKinematics A = pointKinematics(d, c.bodyA, c.pointA, withAcc);
        const PointKinematics B = pointKinematics(d, c.bodyB, c.pointB, withAcc);
        const Vec3 dx = A.x - B.x;
        const double L = dx.norm();
        const Vec3 u = dx / L;
        d.phi(c.row) = L - c.length;
        if (!withVel) break;
        const Vec3 dv = A.v - B.v;
        const double Ldot = u.dot(dv);
        d.phiDot(c.row) = Ldot;
        if (!withAcc) break;
        d.phiDDot(c.row) = u.dot(A.a - B.a) + (dv.squaredNorm() - Ldot * Ldot) / L;
        break;
      }
      case CutJointType::Driver: {
        const Body& b = model.bodies[c.drivenBody];
        const SignalValue& s = d.driverTargets[c.driverSlot];
        const int k = c.drivenCoordinate;
        d.phi(c.row) = q(b.qIndex + k) - s.value;
        if (withVel) d.phiDot(c.row) = (*v)(b.vIndex + k) - s.rate;
        if (withAcc) d.phiDDot(c.row) = (*a)(b.vIndex + k) - s.accel;
        break;
      }
    }
  }
}

// Adds scale * (d x / d q) of a world point x on `body` to the rows `out`,
// for the joints strictly below `stopBody` on the path to the root.
template <typename Rows>
void addPointJacobian(const Model& model, const Data& d, int body, const Vec3& x, int stopBody,
                      const Eigen::Matrix<double, Rows::RowsAtCompileTime, 3>& scale, Eigen::MatrixXd& J, int row,
                      double sign) {
  for (int k = body; k >= 0 && k != stopBody; k = model.bodies[k].parent) {
    const Body& b = model.bodies[k];
    for (int c = 0; c < b.nv; ++c) {
      const Vec6 s = d.S.col(b.vIndex + c);
      const Vec3 ang = d.R[k] * s.tail<3>();
      const Vec3 lin = d.R[k] * s.head<3>() + ang.cross(x - d.p[k]);
      J.block<Rows::RowsAtCompileTime, 1>(row, b.vIndex + c) += sign * (scale * lin);
    }
  }
}

}  // namespace

void constraintResiduals(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                         const Eigen::VectorXd& a, Data& d) {
  evaluate(model, q, &v, &a, d);
}

void constraintPositions(const Model& model, const Eigen::VectorXd& q, Data& d) {
  evaluate(model, q, nullptr, nullptr, d);
}

void applyConstraintWrenches(const Model& model, const Eigen::VectorXd& lambda, Data& d) {
  for (const CutJoint& c : model.cutJoints) {
    if (c.type == CutJointType::Driver) continue;
    const Vec3 xa = pointPosition(d, c.bodyA, c.pointA);
    const Vec3 xb = pointPosition(d, c.bodyB, c.pointB);
    Vec3 force;
    if (c.type == CutJointType::Spherical) {
      force = bodyRotation(d, c.frameBody) * lambda.segment<3>(c.row);
    } else {
      const Vec3 dx = xa - xb;
      force = lambda(c.row) * dx / dx.norm();
    }
    // fext enters the residual with a minus sign; Phi_q^T lambda with a plus.
    addWorldForce(d, c.bodyA, xa, -force);
    addWorldForce(d, c.bodyB, xb, force);
  }
}

void addDriverReactions(const Model& model, const Eigen::VectorXd& lambda, Data& d) {
  for (const CutJoint& c : model.cutJoints)
    if (c.type == CutJointType::Driver) d.tau(model.bodies[c.drivenBody].vIndex + c.drivenCoordinate) += lambda(c.row);
}

void constraintJacobian(const Model& model, const Data& d, Eigen::MatrixXd& J) {
  J.setZero();
  for (const CutJoint& c : model.cutJoints) {
    switch (c.type) {
      case CutJointType::Spherical: {
        const Eigen::Matrix3d RCt = bodyRotation(d, c.frameBody).transpose();
        const Vec3 xa = pointPosition(d, c.bodyA, c.pointA);
        const Vec3 xb = pointPosition(d, c.bodyB, c.pointB);
        addPointJacobian<Eigen::Matrix<double, 3, 1>>(model, d, c.bodyA, xa, c.frameBody, RCt, J, c.row, 1.0);
        addPointJacobian<Eigen::Matrix<double, 3, 1>>(model, d, c.bodyB, xb, c.frameBody, RCt, J, c.row, -1.0);
        break;
      }
      case CutJointType::Distance: {
        const Vec3 xa = pointPosition(d, c.bodyA, c.pointA);
        const Vec3 xb = pointPosition(d, c.bodyB, c.pointB);
        const Eigen::Matrix<double, 1, 3> u = (xa - xb).normalized().transpose();
        // Joints at or above the common ancestor move both ends rigidly: no change of length.
        addPointJacobian<Eigen::Matrix<double, 1, 1>>(model, d, c.bodyA, xa, c.frameBody, u, J, c.row, 1.0);
        addPointJacobian<Eigen::Matrix<double, 1, 1>>(model, d, c.bodyB, xb, c.frameBody, u, J, c.row, -1.0);
        break;
      }
      case CutJointType::Driver:
        J(c.row, model.bodies[c.drivenBody].vIndex + c.drivenCoordinate) = 1.0;
        break;
    }
  }
}

}  // namespace bdfcar::mb
