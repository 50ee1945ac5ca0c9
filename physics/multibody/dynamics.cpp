#include "multibody/dynamics.h"

namespace bdfcar::mb {

void clearForces(const Model& model, Data& d) {
  for (size_t i = 0; i < model.bodies.size(); ++i) d.fext[i].setZero();
}

void applyGravity(const Model& model, Data& d) {
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    const Vec3 fb = b.mass * (d.R[i].transpose() * model.gravity);
    d.fext[i].head<3>() += fb;
    d.fext[i].tail<3>() += b.com.cross(fb);
  }
}

void applySprings(const Model& model, Data& d) {
  for (size_t k = 0; k < model.springs.size(); ++k) {
    const SpringDamper& s = model.springs[k];
    if (s.tableBody >= 0) {
      // Length from the joint table; the force does virtual work F dL on the joint coordinates.
      const Body& b = model.bodies[s.tableBody];
      const SplineGrid::Sample& t = d.tableSamples[b.table];
      const auto& rate = d.tableRates[b.table];
      const int c = s.tableComponent;
      double Ldot = 0;
      for (int j = 0; j < b.nv; ++j) Ldot += t.grad[c][j] * rate[j];
      const double f = s.force(t.f[c], Ldot);
      d.springLength[k] = t.f[c];
      d.springLengthRate[k] = Ldot;
      d.springForce[k] = f;
      for (int j = 0; j < b.nv; ++j) d.jointForce(b.vIndex + j) += f * t.grad[c][j];
      continue;
    }
    const Vec3 xa = pointPosition(d, s.bodyA, s.pointA);
    const Vec3 xb = pointPosition(d, s.bodyB, s.pointB);
    const Vec3 dvec = xa - xb;
    const double L = dvec.norm();
    const Vec3 u = dvec / L;
    const double Ldot = u.dot(pointVelocity(d, s.bodyA, s.pointA) - pointVelocity(d, s.bodyB, s.pointB));
    const double f = s.force(L, Ldot);
    d.springLength[k] = L;
    d.springLengthRate[k] = Ldot;
    d.springForce[k] = f;
    addWorldForce(d, s.bodyA, xa, f * u);
    addWorldForce(d, s.bodyB, xb, -f * u);
  }
}

void inverseDynamics(const Model& model, Data& d) {
  const int nb = static_cast<int>(model.bodies.size());
  for (int i = 0; i < nb; ++i) {
    const Mat6& I = model.bodies[i].spatialInertia;
    const Vec6 h = I * d.vel[i];
    d.f[i].noalias() = I * d.acc[i];
    d.f[i] += crossForce(d.vel[i], h) - d.fext[i];
  }
  for (int i = nb - 1; i >= 0; --i) {
    const Body& b = model.bodies[i];
    for (int k = 0; k < b.nv; ++k) d.tau(b.vIndex + k) = d.S.col(b.vIndex + k).dot(d.f[i]);
    if (b.parent >= 0) d.f[b.parent] += d.Xup[i].applyTransposeForce(d.f[i]);
  }
}

void addPathJointForces(const Model& model, const Data& d, int body, Vec6 f, double scale,
                        Eigen::Ref<Eigen::VectorXd> out) {
  for (int i = body; i >= 0; i = model.bodies[i].parent) {
    const Body& b = model.bodies[i];
    for (int k = 0; k < b.nv; ++k) out(b.vIndex + k) += scale * d.S.col(b.vIndex + k).dot(f);
    if (b.parent >= 0) f = d.Xup[i].applyTransposeForce(f);
  }
}

void massMatrix(const Model& model, Data& d, Eigen::MatrixXd& M) {
  const int nb = static_cast<int>(model.bodies.size());
  M.setZero();
  for (int i = 0; i < nb; ++i) d.Ic[i] = model.bodies[i].spatialInertia;
  for (int i = nb - 1; i >= 0; --i) {
    const Body& b = model.bodies[i];
    if (b.parent >= 0) {
      const Mat6 X = d.Xup[i].motionMatrix();
      d.Ic[b.parent].noalias() += X.transpose() * d.Ic[i] * X;
    }
  }
  Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> F;
  for (int i = 0; i < nb; ++i) {
    const Body& b = model.bodies[i];
    F.noalias() = d.Ic[i] * d.S.middleCols(b.vIndex, b.nv);
    M.block(b.vIndex, b.vIndex, b.nv, b.nv).noalias() = d.S.middleCols(b.vIndex, b.nv).transpose() * F;
    int j = i;
    while (model.bodies[j].parent >= 0) {
      // Transform F to the parent's coordinates (each column is a force).
      for (int c = 0; c < b.nv; ++c) F.col(c) = d.Xup[j].applyTransposeForce(F.col(c));
      j = model.bodies[j].parent;
      const Body& bj = model.bodies[j];
      auto blk = M.block(bj.vIndex, b.vIndex, bj.nv, b.nv);
      blk.noalias() = d.S.middleCols(bj.vIndex, bj.nv).transpose() * F;
      M.block(b.vIndex, bj.vIndex, b.nv, bj.nv) = blk.transpose();
    }
  }
}

double kineticEnergy(const Model& model, const Data& d) {
  double T = 0;
  for (size_t i = 0; i < model.bodies.size(); ++i)
    T += 0.5 * d.vel[i].dot(model.bodies[i].spatialInertia * d.vel[i]);
  return T;
}

double potentialEnergy(const Model& model, const Data& d) {
  double V = 0;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    V -= b.mass * model.gravity.dot(d.p[i] + d.R[i] * b.com);
  }
  return V;
}

}  // namespace bdfcar::mb
