#include "vehicle/motion_ratio.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <optional>

#include "multibody/constraints.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "multibody/multibody_dae.h"
#include "vehicle/equilibrium.h"
#include "vehicle/linkage_sweep.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

std::vector<MotionRatio> motionRatios(const Vehicle& v) {
  const mb::Model& m = v.model;
  mb::Data d = mb::makeData(m);
  const Eigen::VectorXd q = designPositions(v);
  mb::updatePositions(m, q, d);
  Eigen::MatrixXd J(m.nc, m.nv);
  mb::constraintJacobian(m, d, J);
  // Held: chassis, rack, wheel spins. The remaining motions form the null space.
  std::vector<int> free;
  for (const mb::Body& b : m.bodies) {
    const int i = static_cast<int>(&b - m.bodies.data());
    bool spin = false;
    for (const WheelLayout& w : v.layout.wheels) spin |= w.spindle == i;
    if (i == v.layout.chassis || i == v.layout.rack || spin) continue;
    for (int k = 0; k < b.nv; ++k) free.push_back(b.vIndex + k);
  }
  // No suspension coordinates (wheels on the chassis): no spring moves with a
  // wheel, and the SVD below would read the first of no singular values.
  if (free.empty()) {
    std::vector<MotionRatio> none(m.springs.size());
    for (size_t k = 0; k < none.size(); ++k) none[k].element = m.springs[k].name;
    return none;
  }
  Eigen::MatrixXd Jf(m.nc, free.size());
  for (size_t j = 0; j < free.size(); ++j) Jf.col(j) = J.col(free[j]);
  // Null-space basis of the constraints over the free coordinates (all of
  // them when there are no cut joints: an SVD of no rows is undefined).
  Eigen::MatrixXd N = Eigen::MatrixXd::Identity(free.size(), free.size());
  if (m.nc > 0) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jf, Eigen::ComputeFullV);
    const int rank = static_cast<int>((svd.singularValues().array() > 1e-9 * svd.singularValues()(0)).count());
    N = svd.matrixV().rightCols(free.size() - rank);
  }
  // Velocity of a world point of a body along a joint-space direction, by finite differences of positions.
  auto pointRate = [&](const Eigen::VectorXd& dq, int body, const Eigen::Vector3d& local) {
    const double e = 1e-7;
    Eigen::VectorXd qp(m.nq), qm(m.nq);
    mb::retract(m, q, e * dq, qp);
    mb::retract(m, q, -e * dq, qm);
    mb::updatePositions(m, qp, d);
    const Eigen::Vector3d xp = mb::pointPosition(d, body, local);
    mb::updatePositions(m, qm, d);
    const Eigen::Vector3d xm = mb::pointPosition(d, body, local);
    return Eigen::Vector3d((xp - xm) / (2 * e));
  };
  auto toFull = [&](const Eigen::VectorXd& n) {
    Eigen::VectorXd dq = Eigen::VectorXd::Zero(m.nv);
    for (size_t j = 0; j < free.size(); ++j) dq(free[j]) = n(j);
    return dq;
  };
  // Wheel-centre heave per null-space direction; combine into pure single-wheel travel.
  const int k = static_cast<int>(N.cols());
  Eigen::MatrixXd Z(4, k);
  for (int c = 0; c < k; ++c)
    for (int w = 0; w < 4; ++w) Z(w, c) = pointRate(toFull(N.col(c)), v.layout.wheels[w].spindle, Eigen::Vector3d::Zero()).z();
  std::vector<MotionRatio> out;
  const Eigen::MatrixXd travel = Z.completeOrthogonalDecomposition().pseudoInverse();  // k x 4: unit heave of each wheel
  for (const mb::SpringDamper& s : m.springs) {
    MotionRatio r;
    r.element = s.name;
    for (int w = 0; w < 4; ++w) {
      const Eigen::VectorXd dq = toFull(N * travel.col(w));
      mb::updatePositions(m, q, d);
      const Eigen::Vector3d u =
          (mb::pointPosition(d, s.bodyA, s.pointA) - mb::pointPosition(d, s.bodyB, s.pointB)).normalized();
      const double rate = u.dot(pointRate(dq, s.bodyA, s.pointA) - pointRate(dq, s.bodyB, s.pointB));
      if (std::abs(rate) > 1e-6) {
        r.wheel = w;
        r.ratio = rate;
      }
    }
    out.push_back(r);
  }
  return out;
}

void indexSuspensionChannels(Vehicle& v) {
  mb::Data d = mb::makeData(v.model);
  mb::updatePositions(v.model, designPositions(v), d);
  const int ch = v.layout.chassis;
  for (int w = 0; w < 4; ++w)
    v.layout.wheelCentreAtDesign[w] = d.R[ch].transpose() * (d.p[v.layout.wheels[w].spindle] - d.p[ch]);
  v.layout.springCorner.clear();
  for (const MotionRatio& r : motionRatios(v)) v.layout.springCorner.push_back(r.wheel);
}

double roadWheelAnglePerSteer(const Vehicle& v) {
  // Each wheel held at its design height while the rack moves, as the K&C
  // rig's steering ratio: the linkage assembled from its design positions
  // with only the rack moved closes its loops by moving the suspension too
  // (Newton's least-norm closure slides a MacPherson strut and lifts one
  // wheel and drops the other), which took 7 % off the sedan's angle and
  // made the derived rungs, whose wheel travels are coordinates held at
  // design here, disagree with their own linkage.
  const double steer = 0.05;
  const double rackPerSteer = v.layout.rackAxisSign * -v.spec.steering.rackTravelFull;
  auto meanFrontAngle = [&](const mb::Data& d) {
    double angle = 0;
    for (int w = 0; w < 2; ++w) {
      const Eigen::Vector3d n = d.R[v.layout.chassis].transpose() * d.R[v.layout.wheels[w].spindle].col(1);
      angle += 0.5 * pm::atan2(-n.x(), n.y());
    }
    return angle;
  };
  double angle[2] = {0, 0};
  std::optional<LinkageSweep> rig;
  if (v.fidelity == Fidelity::Linkage) {
    try {
      rig.emplace(v);
    } catch (const mb::ModelError&) {
      // Not one free motion per wheel with the rack held (no rig can hold
      // its wheels): the plain assembly below, suspension free.
    }
  }
  if (rig) {
    const double rack0 = rig->design()(v.layout.rackQ);
    for (int k = 0; k < 2; ++k) {
      Eigen::VectorXd q = rig->design();
      if (!rig->solve(0.0, rack0 + (k == 0 ? steer : -steer) * rackPerSteer, q)) return 0;
      angle[k] = meanFrontAngle(rig->at(q));
    }
  } else {
    const mb::Model& m = v.model;
    mb::MultibodyDae dae(m);
    mb::Data d = mb::makeData(m);
    for (int k = 0; k < 2; ++k) {
      Eigen::VectorXd q = designPositions(v);
      setRackTravel(v, q, (k == 0 ? steer : -steer) * rackPerSteer);
      std::string msg;
      if (!assemble(v, dae, 0, q, msg)) return 0;
      mb::updatePositions(m, q, d);
      angle[k] = meanFrontAngle(d);
    }
  }
  return (angle[0] - angle[1]) / (2 * steer);
}

}  // namespace bdfcar::vehicle
