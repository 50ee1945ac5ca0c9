#include "vehicle/equilibrium.h"

#include <Eigen/Geometry>
#include <cstdio>

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "integrator/dae_blocks.h"
#include "multibody/kinematics.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

using integ::Mat;
using integ::Vec;

namespace {

// Coordinates a driver prescribes: the rack (and, in a kinematic model, the
// rack travel of the steered corners' tables).
void addDrivenCoordinates(const mb::Model& m, std::vector<int>& held) {
  for (const mb::CutJoint& c : m.cutJoints)
    if (c.type == mb::CutJointType::Driver) held.push_back(m.bodies[c.drivenBody].vIndex + c.drivenCoordinate);
}

}  // namespace

std::vector<int> heldCoordinates(const Vehicle& v) {
  const mb::Body& base = v.model.bodies[v.layout.base];
  // Free joint velocity order: linear (body x, y, z), angular (roll, pitch,
  // yaw); a planar joint has x, y and yaw only.
  std::vector<int> held = {base.vIndex + 0, base.vIndex + 1, base.vIndex + (base.joint == mb::JointType::Planar ? 2 : 5)};
  addDrivenCoordinates(v.model, held);
  for (const WheelLayout& w : v.layout.wheels) held.push_back(w.spinV);
  if (v.layout.engine >= 0) held.push_back(v.layout.engineV);
  std::sort(held.begin(), held.end());
  return held;
}

namespace {

std::vector<int> complement(int n, const std::vector<int>& held) {
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (!std::binary_search(held.begin(), held.end(), i)) free.push_back(i);
  return free;
}

// Constraint rows that are not rheonomic drivers (those involve held coordinates only).
std::vector<int> loopRows(const mb::Model& m) {
  std::vector<int> rows;
  for (const mb::CutJoint& c : m.cutJoints)
    if (c.type != mb::CutJointType::Driver)
      for (int r = 0; r < c.rows; ++r) rows.push_back(c.row + r);
  return rows;
}

}  // namespace

bool assemble(const Vehicle& v, integ::Dae& dae, double t, Vec& q, std::string& message) {
  const integ::DaeSizes n = dae.sizes();
  std::vector<int> held;
  const mb::Body& base = v.model.bodies[v.layout.base];
  for (int i = 0; i < base.nv; ++i) held.push_back(base.vIndex + i);
  addDrivenCoordinates(v.model, held);
  std::sort(held.begin(), held.end());
  const std::vector<int> free = complement(n.nv, held), rows = loopRows(v.model);
  integ::Residual r;
  r.resize(n);
  Mat J(n.nc, n.nv);
  Vec zv = Vec::Zero(n.nv), zc = Vec::Zero(n.nc), dq = Vec::Zero(n.nv), qn(n.nq);
  integ::Message msg;
  for (int it = 0; it < 30; ++it) {
    dae.residual(t, q, zv, zv, zc, r, true, msg);
    double worst = 0;
    for (int i : rows) worst = std::max(worst, std::abs(r.phi(i)));
    if (worst < 1e-12) return true;
    dae.constraintJacobian(t, q, J);
    Mat Jf(rows.size(), free.size());
    Vec phi(rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
      phi(i) = r.phi(rows[i]);
      for (size_t j = 0; j < free.size(); ++j) Jf(i, j) = J(rows[i], free[j]);
    }
    const Vec step = Jf.completeOrthogonalDecomposition().solve(-phi);  // minimum-norm correction
    dq.setZero();
    for (size_t j = 0; j < free.size(); ++j) dq(free[j]) = step(j);
    dae.retract(q, dq, qn);
    q = qn;
  }
  message = "assembly did not converge: the hardpoints cannot close the loops";
  return false;
}

std::optional<std::string> farFromDesign(const Vehicle& v, const Vec& design, const Vec& assembled) {
  const mb::Model& m = v.model;
  mb::Data d0 = mb::makeData(m), d1 = mb::makeData(m);
  mb::updatePositions(m, design, d0);
  mb::updatePositions(m, assembled, d1);
  const int ch = v.layout.chassis;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    // Relative to the chassis (the assembly holds it; a start pose moves both).
    const Mat3 R0 = d0.R[ch].transpose() * d0.R[i], R1 = d1.R[ch].transpose() * d1.R[i];
    const Vec3 p0 = d0.R[ch].transpose() * (d0.p[i] - d0.p[ch]), p1 = d1.R[ch].transpose() * (d1.p[i] - d1.p[ch]);
    const double move = (p1 - p0).norm();
    const double turn = Eigen::AngleAxisd(R0.transpose() * R1).angle();
    if (move <= kMaxAssemblyMove && turn <= kMaxAssemblyTurn) continue;
    const BodySpec* spec = nullptr;
    for (const BodySpec& b : v.spec.bodies)
      if (b.name == m.bodies[i].name) spec = &b;
    char text[400];
    std::snprintf(text, sizeof text,
                  "%s%s%d: closing the loops moved body '%s' %.1f mm and turned it %.1f deg from its design pose "
                  "(at most %.0f mm and %.1f deg): its hardpoints do not close the loops as drawn (a link's end in "
                  "the wrong place?)",
                  spec ? spec->file.c_str() : v.spec.sourceFile.c_str(), ":", spec ? spec->line : 0,
                  m.bodies[i].name.c_str(), move * 1e3, turn * 180 / M_PI, kMaxAssemblyMove * 1e3,
                  kMaxAssemblyTurn * 180 / M_PI);
    return std::string(text);
  }
  return std::nullopt;
}

EquilibriumReport settleStatic(const Vehicle& v, mb::MultibodyDae& dae, VehicleForces& forces, double t, Vec& q,
                               Vec& lambda) {
  EquilibriumReport rep;
  const integ::DaeSizes n = dae.sizes();
  const std::vector<int> free = complement(n.nv, heldCoordinates(v)), rows = loopRows(v.model);
  const int nf = static_cast<int>(free.size()), nr = static_cast<int>(rows.size());
  integ::Residual r;
  r.resize(n);
  integ::BlockWorkspace ws;
  ws.resize(n);
  integ::StateDerivatives dx;
  dx.resize(n);
  Mat J(n.nc, n.nv), A(nf + nr, nf + nr);
  Vec zv = Vec::Zero(n.nv), b(nf + nr), dq = Vec::Zero(n.nv), qn(n.nq);
  integ::Message msg;
  long count = 0;
  forces.reset(t);
  const double weight = -v.model.totalMass() * v.model.gravity.z();
  for (int it = 0; it < 60; ++it) {
    forces.reset(t);
    dae.beginStep(t, q, zv);  // terrain under the wheels at this configuration
    dae.residual(t, q, zv, zv, lambda, r, true, msg);
    double fmax = 0, pmax = 0;
    for (int i : free) fmax = std::max(fmax, std::abs(r.F(i)));
    for (int i : rows) pmax = std::max(pmax, std::abs(r.phi(i)));
    rep.iterations = it;
    rep.forceResidual = fmax;
    rep.constraintResidual = pmax;
    if (fmax < 1e-7 * weight && pmax < 1e-12) {
      rep.converged = true;
      break;
    }
    integ::stateDerivativeBlocks(dae, t, q, zv, zv, lambda, dx, ws, count);
    dae.constraintJacobian(t, q, J);
    A.setZero();
    for (int i = 0; i < nf; ++i) {
      for (int j = 0; j < nf; ++j) A(i, j) = dx.Fq(free[i], free[j]);
      for (int k = 0; k < nr; ++k) A(i, nf + k) = J(rows[k], free[i]);
      b(i) = -r.F(free[i]);
    }
    for (int k = 0; k < nr; ++k) {
      for (int j = 0; j < nf; ++j) A(nf + k, j) = J(rows[k], free[j]);
      b(nf + k) = -r.phi(rows[k]);
    }
    const Vec sol = A.partialPivLu().solve(b);
    if (!sol.allFinite()) {
      rep.message = "static equilibrium: singular system (a coordinate without stiffness at rest?)";
      return rep;
    }
    dq.setZero();
    for (int j = 0; j < nf; ++j) dq(free[j]) = sol(j);
    for (int k = 0; k < nr; ++k) lambda(rows[k]) += sol(nf + k);
    // Limit the first steps: the tyres' contact switches on and off with large moves.
    const double scale = std::min(1.0, 0.05 / std::max(1e-12, dq.lpNorm<Eigen::Infinity>()));
    dae.retract(q, scale * dq, qn);
    q = qn;
  }
  if (!rep.converged) rep.message = "static equilibrium did not converge";
  // Driver multipliers balance the held rack: F_rack + lambda = 0.
  dae.residual(t, q, zv, zv, lambda, r, true, msg);
  for (const mb::CutJoint& c : v.model.cutJoints)
    if (c.type == mb::CutJointType::Driver) lambda(c.row) -= r.F(v.model.bodies[c.drivenBody].vIndex);

  // Report.
  dae.evaluateKinematics(t, q, zv);
  const mb::Data& d = dae.data();
  const int ch = v.layout.chassis;
  const Eigen::Matrix3d& R = d.R[ch];
  rep.chassisHeight = d.p[ch].z();
  rep.comHeight = (d.p[ch] + R * v.model.bodies[ch].com).z();
  rep.roll = pm::atan2(R(2, 1), R(2, 2));
  rep.pitch = -pm::asin(std::clamp(R(2, 0), -1.0, 1.0));
  for (int w = 0; w < 4; ++w) {
    rep.wheelLoads[w] = forces.outputs()[w].out.Fz;
    rep.totalLoad += rep.wheelLoads[w];
  }
  rep.weight = weight;
  return rep;
}

}  // namespace bdfcar::vehicle
