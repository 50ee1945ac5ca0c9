// The planar joint (the base of the planar vehicle model) against the free
// joint it restricts: a body with an offset centre of mass and a hinged child,
// on a planar joint and on a free joint held in the plane (z, roll and pitch
// zero), must have the same poses, velocities and inverse dynamics; and the
// joint's manifold operations must be consistent with each other.
#include <gtest/gtest.h>

#include <cmath>

#include "multibody/data.h"
#include "multibody/dynamics.h"
#include "multibody/joint.h"
#include "multibody/kinematics.h"

namespace bdfcar::mb {
namespace {

Model twoBodies(JointType base) {
  ModelBuilder mb;
  Body b;
  b.name = "base";
  b.mass = 40.0;
  b.com = Vec3(0.3, -0.1, 0.25);
  b.inertia << 3.0, 0.2, 0.1, 0.2, 5.0, -0.3, 0.1, -0.3, 6.0;
  b.joint = base;
  b.inParent.origin = Vec3(0, 0, 0.4);  // the plane is 0.4 m above the world origin
  const int i = mb.addBody(b);
  Body c;
  c.name = "flap";
  c.mass = 5.0;
  c.com = Vec3(0.0, 0.2, 0.1);
  c.inertia = Vec3(0.3, 0.2, 0.4).asDiagonal();
  c.parent = i;
  c.joint = JointType::Revolute;
  c.inParent.origin = Vec3(1.0, 0.5, 0.3);
  c.inParent.axes = rotX(0.4) * rotY(-0.2);  // a hinge axis out of the plane
  mb.addBody(c);
  return mb.build();
}

TEST(PlanarJoint, MovesAndLoadsAsAFreeJointHeldInThePlane) {
  const Model planar = twoBodies(JointType::Planar), free = twoBodies(JointType::Free);
  ASSERT_EQ(planar.nv, 4);
  ASSERT_EQ(free.nv, 7);
  const double x = 1.3, y = -0.7, yaw = 0.9, u = 12.0, w = -1.5, r = 0.6, hinge = 0.3, hingeRate = -2.0;
  const double au = 0.8, aw = -3.0, ar = 1.7, hingeAcc = 4.0;
  Eigen::VectorXd qp(4), vp(4), ap(4), qf(8), vf = Eigen::VectorXd::Zero(7), af = Eigen::VectorXd::Zero(7);
  qp << x, y, yaw, hinge;
  vp << u, w, r, hingeRate;
  ap << au, aw, ar, hingeAcc;
  const Quat rot(Eigen::AngleAxisd(yaw, Vec3::UnitZ()));
  qf << x, y, 0.0, rot.w(), rot.x(), rot.y(), rot.z(), hinge;
  vf(0) = u, vf(1) = w, vf(5) = r, vf(6) = hingeRate;
  af(0) = au, af(1) = aw, af(5) = ar, af(6) = hingeAcc;
  Data dp = makeData(planar), df = makeData(free);
  for (auto [m, d, q, v, a] : {std::tie(planar, dp, qp, vp, ap), std::tie(free, df, qf, vf, af)}) {
    updatePositions(m, q, d);
    updateVelocities(m, v, d);
    updateAccelerations(m, a, d);
    clearForces(m, d);
    applyGravity(m, d);
    inverseDynamics(m, d);
  }
  for (int b = 0; b < 2; ++b) {
    EXPECT_LT((dp.p[b] - df.p[b]).norm(), 1e-12) << b;
    EXPECT_LT((dp.R[b] - df.R[b]).norm(), 1e-12) << b;
    EXPECT_LT((dp.vel[b] - df.vel[b]).norm(), 1e-12) << b;
  }
  // The generalised forces of the shared coordinates: forward, sideways, yaw, hinge.
  const int freeIndex[4] = {0, 1, 5, 6};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(dp.tau(k), df.tau(freeIndex[k]), 1e-9 * (1 + std::abs(df.tau(freeIndex[k])))) << k;
}

TEST(PlanarJoint, RetractionLocalCoordinatesAndTheirRateAgree) {
  const double base[3] = {2.0, -1.0, 0.7}, dq[3] = {0.3, -0.2, 0.4};
  double moved[3], back[3];
  jointRetract(JointType::Planar, base, dq, moved);
  jointLocal(JointType::Planar, base, moved, back);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], dq[k], 1e-14);
  // The rate of the local coordinates at delta = dq for a velocity v, against
  // central differences of the local coordinates along the motion: the
  // position moves by Rz(angle) v_lin dt, the angle by v_ang dt.
  const double v[3] = {5.0, -1.0, 0.8}, dt = 1e-6;
  double rate[3], plus[3], minus[3], lp[3], lm[3];
  jointLocalRate(JointType::Planar, dq, v, rate);
  const double c = std::cos(moved[2]), s = std::sin(moved[2]);
  for (int sign : {+1, -1}) {
    double* out = sign > 0 ? plus : minus;
    out[0] = moved[0] + sign * dt * (c * v[0] - s * v[1]);
    out[1] = moved[1] + sign * dt * (s * v[0] + c * v[1]);
    out[2] = moved[2] + sign * dt * v[2];
  }
  jointLocal(JointType::Planar, base, plus, lp);
  jointLocal(JointType::Planar, base, minus, lm);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(rate[k], (lp[k] - lm[k]) / (2 * dt), 1e-7) << k;
}

}  // namespace
}  // namespace bdfcar::mb
