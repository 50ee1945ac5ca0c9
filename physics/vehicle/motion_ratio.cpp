#include "vehicle/motion_ratio.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>

#include "multibody/constraints.h"
#include "multibody/kinematics.h"
#include "multibody/multibody_dae.h"
#include "vehicle/equilibrium.h"
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
  const mb::Model& m = v.model;
  mb::MultibodyDae dae(m);
  mb::Data d = mb::makeData(m);
  const double steer = 0.05;
  double angle[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const double s = k == 0 ? steer : -steer;
    Eigen::VectorXd q = designPositions(v);
    setRackTravel(v, q, v.layout.rackAxisSign * -v.spec.steering.rackTravelFull * s);
    std::string msg;
    if (!assemble(v, dae, 0, q, msg)) return 0;
    mb::updatePositions(m, q, d);
    for (int w = 0; w < 2; ++w) {
      const Eigen::Vector3d n = d.R[v.layout.chassis].transpose() * d.R[v.layout.wheels[w].spindle].col(1);
      angle[k] += 0.5 * pm::atan2(-n.x(), n.y());
    }
  }
  return (angle[0] - angle[1]) / (2 * steer);
}

}  // namespace bdfcar::vehicle
