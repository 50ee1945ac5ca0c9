#include "multibody/kinematics.h"

#include <cmath>

#include "multibody/joint.h"
#include "portable_math.h"

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
  const auto [s, c] = pm::sincos(t);
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

bool isTabulated(const Body& b) {
  return b.joint == JointType::Tabulated1 || b.joint == JointType::Tabulated2;
}

// A tabulated joint at coordinates c: the body's rotation R and origin t in
// the parent body frame, its subspace columns (body coordinates) and their
// derivatives with respect to c. With the angles a = (psi, phi, theta) of
// R = rest Rz(psi) Rx(phi) Ry(theta), the body-frame angular velocity is
// E(phi, theta) a_dot; d R / d c_l = R [w_l]x turns d(R^T dt/dc_k)/dc_l into
// -w_l x (R^T dt/dc_k) + R^T d2t/dc_k dc_l.
void tabulatedPose(const Model& model, const Body& b, const double* c, Data& d, Mat3& R, Vec3& t) {
  const JointTable& table = model.tables[b.table];
  SplineGrid::Sample& s = d.tableSamples[b.table];
  table.grid.eval(c[0], b.nv > 1 ? c[1] : 0.0, s);
  const double psi = s.f[3], phi = s.f[4], theta = s.f[5];
  const auto [sp, cp] = pm::sincos(psi);
  const auto [sf, cf] = pm::sincos(phi);
  const auto [st, ct] = pm::sincos(theta);
  Mat3 M;  // Rz(psi) Rx(phi) Ry(theta), from the sines and cosines once
  M << cp * ct - sp * sf * st, -sp * cf, cp * st + sp * sf * ct,  //
      sp * ct + cp * sf * st, cp * cf, sp * st - cp * sf * ct,    //
      -cf * st, sf, cf * ct;
  R.noalias() = table.rest * M;
  t = Vec3(s.f[0], s.f[1], s.f[2]);
  Mat3 E, Ephi = Mat3::Zero(), Etheta = Mat3::Zero();
  E << -st * cf, ct, 0, sf, 0, 1, ct * cf, st, 0;
  Ephi.col(0) << st * sf, cf, -ct * sf;
  Etheta.col(0) << -ct * cf, 0, -st * cf;
  Etheta.col(1) << -st, 0, ct;
  const Mat3 Rt = R.transpose();
  std::array<Vec3, 2> w, lin;
  for (int k = 0; k < b.nv; ++k) {
    const Vec3 da(s.grad[3][k], s.grad[4][k], s.grad[5][k]);
    w[k] = E * da;
    lin[k] = Rt * Vec3(s.grad[0][k], s.grad[1][k], s.grad[2][k]);
    d.S.col(b.vIndex + k) << lin[k], w[k];
  }
  auto hessIndex = [](int k, int l) { return k + l; };  // (0,0) -> xx, (0,1) -> xy, (1,1) -> yy
  for (int k = 0; k < b.nv; ++k) {
    const Vec3 da(s.grad[3][k], s.grad[4][k], s.grad[5][k]);
    for (int l = 0; l < b.nv; ++l) {
      const int h = hessIndex(k, l);
      const Vec3 d2a(s.hess[3][h], s.hess[4][h], s.hess[5][h]);
      const Vec3 d2t(s.hess[0][h], s.hess[1][h], s.hess[2][h]);
      Vec6& out = d.tableSubspaceDerivatives[b.table][2 * k + l];
      out.head<3>() = -w[l].cross(lin[k]) + Rt * d2t;
      out.tail<3>() = (Ephi * s.grad[4][l] + Etheta * s.grad[5][l]) * da + E * d2a;
    }
  }
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
        // rotX(alpha) rotY(beta) written out, and the subspace's first
        // column (cos beta, 0, sin beta) about the joint frame's axes.
        const auto [sa, ca] = pm::sincos(qi[0]);
        const auto [sb, cb] = pm::sincos(qi[1]);
        Mat3 Rj;
        Rj << cb, 0, sb, sa * sb, ca, -sa * cb, -ca * sb, sa, ca * cb;
        R = throughJointFrames(b, Rj);
        d.secondAngleSinCos[i] = {sb, cb};
        Vec6 s0;
        s0 << 0, 0, 0, cb, 0, sb;
        d.S.col(b.vIndex) = jointToBody(b, s0);
        break;
      }
      case JointType::Spherical: R = throughJointFrames(b, quatToMatrix(qi)); break;
      case JointType::Free:
        R = throughJointFrames(b, quatToMatrix(qi + 3));
        t += b.inParent.axes * Vec3(qi[0], qi[1], qi[2]);
        break;
      case JointType::Planar:
        R = rotateAboutAxis(b, qi[2]);
        t += b.inParent.axes * Vec3(qi[0], qi[1], 0.0);
        break;
      case JointType::Tabulated1:
      case JointType::Tabulated2: tabulatedPose(model, b, qi, d, R, t); break;
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

void updateVelocities(const Model& model, const Eigen::VectorXd& v, Data& d) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    const Vec6 vJ = subspaceTimes(d, b, v);
    if (b.parent < 0)
      d.vel[i] = vJ;
    else
      d.vel[i] = d.Xup[i].applyMotion(d.vel[b.parent]) + vJ;
    d.bias[i] = crossMotion(d.vel[i], vJ);
    if (b.joint == JointType::Universal) {
      // d/dt of the first column (cos beta, 0, sin beta) times alpha_dot,
      // from the sine and cosine updatePositions took.
      const auto [sb, cb] = d.secondAngleSinCos[i];
      const double ab = v(b.vIndex) * v(b.vIndex + 1);
      Vec6 c;
      c << 0, 0, 0, -sb * ab, 0, cb * ab;
      d.bias[i] += jointToBody(b, c);
    }
    if (isTabulated(b)) {
      // Apparent rate of the subspace: sum over k, l of dS_k/dc_l c_dot_l c_dot_k.
      const auto& dS = d.tableSubspaceDerivatives[b.table];
      auto& rates = d.tableRates[b.table];
      for (int k = 0; k < b.nv; ++k) {
        rates[k] = v(b.vIndex + k);
        for (int l = 0; l < b.nv; ++l) d.bias[i] += dS[2 * k + l] * (v(b.vIndex + k) * v(b.vIndex + l));
      }
    }
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
