#include "mechanisms.h"

#include <cmath>

namespace bdfcar::test {

using mb::Body;
using mb::CutJoint;
using mb::CutJointType;
using mb::frameAt;
using mb::JointType;
using mb::Mat3;
using mb::Pose;
using mb::Vec3;

namespace {

Mat3 diag(double a, double b, double c) { return Vec3(a, b, c).asDiagonal(); }

// Rotation about world +y by angle t (maps x to (cos t, 0, -sin t)).
Mat3 aboutY(double t) { return mb::rotY(t); }

Body makeBody(const std::string& name, double m, const Vec3& com, const Mat3& I, int parent, JointType j,
              const mb::JointFrame& inParent, const mb::JointFrame& inChild) {
  Body b;
  b.name = name;
  b.mass = m;
  b.com = com;
  b.inertia = I;
  b.parent = parent;
  b.jointName = name + "_joint";
  b.joint = j;
  b.inParent = inParent;
  b.inChild = inChild;
  return b;
}

}  // namespace

mb::Model pendulum(double L, double m, double rg) {
  mb::ModelBuilder mbld;
  const Mat3 axes = mb::axesWithZ(Vec3::UnitY());
  const double Ic = m * rg * rg;
  mbld.addBody(makeBody("bob", m, Vec3(0, 0, -L), diag(Ic, Ic, Ic), mb::kGround, JointType::Revolute,
                        frameAt(Pose{}, Vec3::Zero(), axes), frameAt(Pose{}, Vec3::Zero(), axes)));
  return mbld.build();
}

FourBar fourBar(double a, double b, double c, double d, double crank0) {
  FourBar fb{mb::Model{}, a, b, c, d, crank0, 0};
  // Planar coordinates (X, Z') with Z' = -z, so that rotation about +y is counter-clockwise.
  const double bx = a * std::cos(crank0), bz = a * std::sin(crank0);
  // Rocker tip C on circles |C - O4| = c and |C - B| = b, upper (open) branch.
  const double ex = d - bx, ez = -bz;  // B -> O4
  const double dist = std::hypot(ex, ez);
  const double along = (b * b - c * c + dist * dist) / (2 * dist);
  const double h = std::sqrt(b * b - along * along);
  const double cx = bx + (along * ex - h * ez) / dist, cz = bz + (along * ez + h * ex) / dist;
  const double rocker0 = std::atan2(cz, cx - d);
  const double cx2 = bx + (along * ex + h * ez) / dist, cz2 = bz + (along * ez - h * ex) / dist;
  // Keep the branch with the tip above the ground link (Z' > 0 at crank0 ~ pi/2).
  fb.rocker0 = (cz >= cz2) ? rocker0 : std::atan2(cz2, cx2 - d);

  mb::ModelBuilder mbld;
  mbld.setGravity(Vec3::Zero());  // lying flat: only inertia drives it
  const Mat3 axes = mb::axesWithZ(Vec3::UnitY());
  const Pose crankPose{aboutY(crank0), Vec3::Zero()};
  const Pose rockerPose{aboutY(fb.rocker0), Vec3(d, 0, 0)};
  const double mc = 1.0, mr = 2.0;
  const int crank = mbld.addBody(makeBody("crank", mc, Vec3(a / 2, 0, 0), diag(1e-4, mc * a * a / 12, mc * a * a / 12),
                                          mb::kGround, JointType::Revolute, frameAt(Pose{}, Vec3::Zero(), axes),
                                          frameAt(crankPose, Vec3::Zero(), axes)));
  const int rocker = mbld.addBody(makeBody("rocker", mr, Vec3(c / 2, 0, 0),
                                           diag(1e-4, mr * c * c / 12, mr * c * c / 12), mb::kGround,
                                           JointType::Revolute, frameAt(Pose{}, Vec3(d, 0, 0), axes),
                                           frameAt(rockerPose, Vec3(d, 0, 0), axes)));
  CutJoint coupler;
  coupler.name = "coupler";
  coupler.type = CutJointType::Distance;
  coupler.bodyA = crank;
  coupler.pointA = Vec3(a, 0, 0);
  coupler.bodyB = rocker;
  coupler.pointB = Vec3(c, 0, 0);
  coupler.length = b;
  mbld.addCutJoint(coupler);
  fb.model = mbld.build();
  return fb;
}

mb::Model sliderCrank(double a, double b) {
  mb::ModelBuilder mbld;
  const Mat3 yAxes = mb::axesWithZ(Vec3::UnitY());
  const Mat3 xAxes = mb::axesWithZ(Vec3::UnitX());
  const double mc = 1.0, mrod = 0.5, ms = 2.0;
  const int crank = mbld.addBody(makeBody("crank", mc, Vec3(a / 2, 0, 0), diag(1e-3, mc * a * a / 12, mc * a * a / 12),
                                          mb::kGround, JointType::Revolute, frameAt(Pose{}, Vec3::Zero(), yAxes),
                                          frameAt(Pose{}, Vec3::Zero(), yAxes)));
  const Pose rodPose{Mat3::Identity(), Vec3(a, 0, 0)};
  const int rod = mbld.addBody(makeBody("rod", mrod, Vec3(b / 2, 0, 0),
                                        diag(2e-3, mrod * b * b / 12, mrod * b * b / 12), crank, JointType::Spherical,
                                        frameAt(Pose{}, Vec3(a, 0, 0)), frameAt(rodPose, Vec3(a, 0, 0))));
  const Pose sliderPose{Mat3::Identity(), Vec3(a + b, 0, 0)};
  const int slider = mbld.addBody(makeBody("slider", ms, Vec3::Zero(), diag(0.01, 0.01, 0.01), mb::kGround,
                                           JointType::Prismatic, frameAt(Pose{}, Vec3(a + b, 0, 0), xAxes),
                                           frameAt(sliderPose, Vec3(a + b, 0, 0), xAxes)));
  CutJoint pin;
  pin.name = "rod_slider";
  pin.type = CutJointType::Spherical;
  pin.bodyA = rod;
  pin.pointA = Vec3(b, 0, 0);
  pin.bodyB = slider;
  pin.pointB = Vec3::Zero();
  mbld.addCutJoint(pin);
  return mbld.build();
}

mb::Model freeBody(double mass, const Eigen::Vector3d& I) {
  mb::ModelBuilder mbld;
  mbld.setGravity(Vec3::Zero());
  mbld.addBody(makeBody("body", mass, Vec3::Zero(), I.asDiagonal(), mb::kGround, JointType::Free, mb::JointFrame{},
                        mb::JointFrame{}));
  return mbld.build();
}

mb::Model paperTopology() {
  mb::ModelBuilder mbld;
  const Pose world{};
  // Every body's frame is parallel to the world at design, at its own origin.
  auto pose = [](const Vec3& p) { return Pose{Mat3::Identity(), p}; };
  const Pose chassisPose = pose(Vec3(0, 0, 0.5));
  const int chassis = mbld.addBody(makeBody("chassis", 1500, Vec3(0, 0, 0.1), diag(500, 2000, 2200), mb::kGround,
                                            JointType::Free, frameAt(world, chassisPose.p), mb::JointFrame{}));
  const Pose rackPose = pose(Vec3(1.0, 0, 0.3));
  const int rack = mbld.addBody(makeBody("rack", 5, Vec3::Zero(), diag(0.5, 0.01, 0.5), chassis, JointType::Prismatic,
                                         frameAt(chassisPose, rackPose.p, mb::axesWithZ(Vec3::UnitY())),
                                         frameAt(rackPose, rackPose.p, mb::axesWithZ(Vec3::UnitY()))));
  auto addLink = [&](const std::string& name, int a, const Vec3& pa, int b, const Vec3& pb, const Pose& posa,
                     const Pose& posb) {
    CutJoint c;
    c.name = name;
    c.type = CutJointType::Distance;
    c.bodyA = a;
    c.pointA = posa.R.transpose() * (pa - posa.p);
    c.bodyB = b;
    c.pointB = posb.R.transpose() * (pb - posb.p);
    c.length = (pa - pb).norm();
    mbld.addCutJoint(c);
  };
  for (int side = 0; side < 2; ++side) {
    const double s = side == 0 ? 1.0 : -1.0;
    const std::string tag = side == 0 ? "_L" : "_R";
    auto P = [s](double x, double y, double z) { return Vec3(x, s * y, z); };
    // Front MacPherson.
    const Vec3 lcaIn = P(1.2, 0.4, 0.2), lcaOut = P(1.22, 0.8, 0.15);
    const Pose lcaPose = pose(lcaIn);
    const int lca = mbld.addBody(makeBody("lca" + tag, 5, P(0.01, 0.2, -0.025),
                                          diag(0.05, 0.02, 0.06), chassis, JointType::Revolute,
                                          frameAt(chassisPose, lcaIn, mb::axesWithZ(Vec3::UnitX())),
                                          frameAt(lcaPose, lcaIn, mb::axesWithZ(Vec3::UnitX()))));
    const Vec3 top = P(1.15, 0.7, 0.8), low = P(1.2, 0.78, 0.4);
    const Pose strutPose = pose(top);
    const int strut = mbld.addBody(makeBody("strut" + tag, 4, (low - top) * 0.5, diag(0.05, 0.05, 0.01), chassis,
                                            JointType::Spherical, frameAt(chassisPose, top), frameAt(strutPose, top)));
    const Vec3 knucklePos = P(1.2, 0.85, 0.3);
    const Pose knucklePose = pose(knucklePos);
    const Mat3 strutAxes = mb::axesWithZ(low - top);
    const int knuckle = mbld.addBody(makeBody("knuckle" + tag, 20, Vec3::Zero(), diag(0.1, 0.08, 0.1), strut,
                                              JointType::Prismatic, frameAt(strutPose, low, strutAxes),
                                              frameAt(knucklePose, low, strutAxes)));
    CutJoint ball;
    ball.name = "ball_joint" + tag;
    ball.type = CutJointType::Spherical;
    ball.bodyA = lca;
    ball.pointA = lcaOut - lcaIn;
    ball.bodyB = knuckle;
    ball.pointB = lcaOut - knucklePos;
    mbld.addCutJoint(ball);
    addLink("tie_rod" + tag, rack, P(1.0, 0.35, 0.3), knuckle, P(1.05, 0.8, 0.28), rackPose, knucklePose);
    mb::SpringDamper strutSpring;
    strutSpring.name = "strut_spring" + tag;
    strutSpring.bodyA = chassis;
    strutSpring.pointA = top - chassisPose.p;
    strutSpring.bodyB = knuckle;
    strutSpring.pointB = low - knucklePos;
    strutSpring.freeLength = (top - low).norm() + 0.02;
    strutSpring.spring.coefficient = 3e4;
    strutSpring.damper.coefficient = 3e3;
    mbld.addSpring(strutSpring);

    // Rear: camber arm revolute, knuckle spherical on it, three distance links.
    const Vec3 armIn = P(-1.3, 0.5, 0.4), armOut = P(-1.3, 0.85, 0.45);
    const Pose armPose = pose(armIn);
    const int arm = mbld.addBody(makeBody("camber_arm" + tag, 4, (armOut - armIn) * 0.5, diag(0.04, 0.01, 0.04),
                                          chassis, JointType::Revolute,
                                          frameAt(chassisPose, armIn, mb::axesWithZ(Vec3::UnitX())),
                                          frameAt(armPose, armIn, mb::axesWithZ(Vec3::UnitX()))));
    const Vec3 rkPos = P(-1.3, 0.9, 0.3);
    const Pose rkPose = pose(rkPos);
    const int rk = mbld.addBody(makeBody("rear_knuckle" + tag, 15, Vec3::Zero(), diag(0.08, 0.06, 0.08), arm,
                                         JointType::Spherical, frameAt(armPose, armOut), frameAt(rkPose, armOut)));
    addLink("trail_link" + tag, chassis, P(-0.8, 0.6, 0.2), rk, P(-1.3, 0.85, 0.15), chassisPose, rkPose);
    addLink("toe_front" + tag, chassis, P(-1.2, 0.4, 0.2), rk, P(-1.2, 0.85, 0.2), chassisPose, rkPose);
    addLink("toe_rear" + tag, chassis, P(-1.5, 0.4, 0.22), rk, P(-1.45, 0.85, 0.22), chassisPose, rkPose);
    mb::SpringDamper rearSpring;
    rearSpring.name = "rear_spring" + tag;
    rearSpring.bodyA = chassis;
    rearSpring.pointA = P(-1.3, 0.8, 0.8) - chassisPose.p;
    rearSpring.bodyB = rk;
    rearSpring.pointB = P(-1.3, 0.85, 0.35) - rkPos;
    rearSpring.freeLength = 0.47;
    rearSpring.spring.coefficient = 2.5e4;
    rearSpring.damper.coefficient = 2.5e3;
    mbld.addSpring(rearSpring);
  }
  return mbld.build();
}

}  // namespace bdfcar::test
