// The K&C rig (physics/vehicle/kc_rig) on the reference sedan against hand
// calculations from its hardpoints (docs/reference-vehicle.md 4.1): vector
// geometry on the named points of the vehicle file, no sweep, no multibody
// model. And what symmetry demands of a symmetric car.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <Eigen/LU>
#include <functional>

#include "config/units.h"
#include "multibody/model_error.h"
#include "vehicle/kc_rig.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar {
namespace {

using config::radToDeg;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

class KcRig : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    sedan_ = new vehicle::Vehicle(vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/sedan.toml"))));
    rig_ = new vehicle::KcResult(vehicle::runKcRig(*sedan_));
  }
  static void TearDownTestSuite() {
    delete rig_;
    delete sedan_;
  }
  // A hardpoint (left side) in the vehicle frame on the ground (z up from
  // the design ground, which is designHeight under the chassis frame).
  static Vec3 point(const char* name) {
    return sedan_->spec.points.at(name) + Vec3(0, 0, sedan_->spec.designHeight);
  }
  static vehicle::Vehicle* sedan_;
  static vehicle::KcResult* rig_;
};
vehicle::Vehicle* KcRig::sedan_ = nullptr;
vehicle::KcResult* KcRig::rig_ = nullptr;

// The MacPherson steering axis: through the strut's top mount and the lower
// ball joint. Caster is its side-view inclination (top rearward +), KPI its
// front-view inclination (top inboard +); scrub radius and trail are where
// it meets the ground relative to the contact point, which is straight under
// the wheel centre (the spindle's axis is the chassis y axis at design).
//
// The rig finds the axis from motion alone: the carrier's instantaneous
// axis as the rack moves with the strut's length held. For a MacPherson
// strut that motion is exactly the rotation about this line (the strut
// length is the distance from the top mount, which a rotation about an axis
// through it keeps; holding it holds the lower arm), so only the rig's
// central differences separate the two: O(h^2) with 10 um of rack, and the
// Newton residual (1e-12 m) over that step, 1e-7 rad. The tolerances
// (0.01 deg, 0.1 mm) are far above that and far below any design change.
// The assembled design differs from the drawn hardpoints by the loops'
// closure (the tie rod's length is given to 6 digits), micrometres.
TEST_F(KcRig, SteeringAxisMatchesTheHardpoints) {
  const Vec3 top = point("STRUT_TOP"), ball = point("LCA_U"), centre = point("SPINDLE_F");
  const Vec3 a = top - ball;
  const double caster = std::atan2(-a.x(), a.z()), kpi = std::atan2(-a.y(), a.z());
  const Vec3 ground = ball - (ball.z() / a.z()) * a;
  const double scrub = centre.y() - ground.y(), trail = ground.x() - centre.x();
  std::printf("hand: caster %.4f deg, KPI %.4f deg, scrub %.2f mm, trail %.2f mm\n", radToDeg(caster), radToDeg(kpi),
              1000 * scrub, 1000 * trail);
  for (int w = 0; w < 2; ++w) {
    const vehicle::KcCorner& c = rig_->corner[w];
    std::printf("rig %s: caster %.4f deg, KPI %.4f deg, scrub %.2f mm, trail %.2f mm\n", vehicle::kCornerNames[w],
                radToDeg(c.caster), radToDeg(c.kingpinInclination), 1000 * c.scrubRadius, 1000 * c.trail);
    ASSERT_TRUE(c.steered);
    EXPECT_NEAR(radToDeg(c.caster), radToDeg(caster), 0.01);
    EXPECT_NEAR(radToDeg(c.kingpinInclination), radToDeg(kpi), 0.01);
    EXPECT_NEAR(c.scrubRadius, scrub, 1e-4);
    EXPECT_NEAR(c.trail, trail, 1e-4);
  }
  EXPECT_FALSE(rig_->corner[2].steered || rig_->corner[3].steered);
  EXPECT_TRUE(std::isnan(rig_->corner[2].caster));
}

// The front corner's motion in bump by hand: a velocity analysis of the
// MacPherson linkage from its hardpoints (rack held). The lower arm turns
// about its pivot axis (LCA_B -> LCA_F) at a unit rate, moving the ball
// joint; the upright turns at Omega about the ball joint, with its point at
// the strut's top mount moving along the strut (the cylindrical joint's line
// must keep passing through the top mount) and the tie rod's length kept:
// three linear equations for Omega. Scaled to a unit rise of the wheel
// centre, it gives bump steer (-Omega_z, toe-in +), camber gain (-Omega_x,
// the top leaning inward as Omega_x > 0 tilts it to -y), the contact
// point's velocity (the upright's point at the ground under the wheel
// centre), and from that the half-track change, the roll centre (the line
// through the contact point perpendicular to its velocity meets the centre
// plane at z = y_c v_y / v_z) and the anti-dive (brakes on the carrier:
// share x v_x x L / h x 100).
//
// The same first-order kinematics as the rig's, reached without it: the
// rig's central differences (0.1 mm of travel, errors O(h^2), 1e-8 of each
// rate) and the assembled design (micrometres from the drawn points) leave
// 1e-6 of each rate at most; the tolerances (0.01 deg/m, 0.1 mm, 0.1 mm/m,
// 0.01 %) are a hundred times that.
struct HandMotion {
  Vec3 omega, centre, contact;  // per metre of wheel-centre rise
  double rollCentre = 0;
};

HandMotion frontCornerByHand(const std::function<Vec3(const char*)>& point) {
  const Vec3 f = point("LCA_F"), b = point("LCA_B"), ball = point("LCA_U"), top = point("STRUT_TOP");
  const Vec3 strut = (top - point("STRUT_LOW")).normalized();
  const Vec3 rackEnd = point("TIEROD_C_F"), armEnd = point("TIEROD_U_F"), wheel = point("SPINDLE_F");
  const Vec3 vBall = (f - b).normalized().cross(ball - b);  // the lower arm at 1 rad/s
  // (vBall + Omega x r) . n = 0  <=>  Omega . (r x n) = -vBall . n
  const Vec3 n1 = strut.cross(Vec3::UnitX()).normalized(), n2 = strut.cross(n1);
  Mat3 A;
  Vec3 rhs;
  const std::pair<Vec3, Vec3> rows[3] = {{top - ball, n1}, {top - ball, n2}, {armEnd - ball, armEnd - rackEnd}};
  for (int i = 0; i < 3; ++i) {
    A.row(i) = rows[i].first.cross(rows[i].second).transpose();
    rhs(i) = -vBall.dot(rows[i].second);
  }
  Vec3 omega = A.fullPivLu().solve(rhs);
  auto velocity = [&](const Vec3& p) { return Vec3(vBall + omega.cross(p - ball)); };
  const double scale = 1.0 / velocity(wheel).z();
  HandMotion m;
  m.omega = scale * omega;
  m.centre = scale * velocity(wheel);
  const Vec3 contact(wheel.x(), wheel.y(), 0.0);
  m.contact = scale * velocity(contact);
  m.rollCentre = contact.y() * m.contact.y() / m.contact.z();
  return m;
}

TEST_F(KcRig, FrontCornerMatchesAVelocityAnalysisByHand) {
  const HandMotion m = frontCornerByHand([](const char* n) { return point(n); });
  const double wheelbase = point("SPINDLE_F").x() - point("SPINDLE_R").x();
  const double antiDive = 100 * rig_->brakeFront * m.contact.x() * wheelbase / rig_->comHeight;
  std::printf("hand: bump steer %.4f deg/m, camber gain %.4f deg/m, half-track change %.3f mm/m, roll centre %.3f mm, "
              "anti-dive %.3f %%\n",
              radToDeg(-m.omega.z()), radToDeg(-m.omega.x()), 1000 * m.contact.y(), 1000 * m.rollCentre, antiDive);
  const vehicle::KcCorner& c = rig_->corner[0];
  std::printf("rig:  bump steer %.4f deg/m, camber gain %.4f deg/m, half-track change %.3f mm/m, roll centre %.3f mm, "
              "anti-dive %.3f %%\n",
              radToDeg(c.bumpSteer), radToDeg(c.camberGain), 1000 * c.halfTrackChange, 1000 * rig_->axle[0].rollCentre,
              rig_->antiDive);
  EXPECT_NEAR(radToDeg(c.bumpSteer), radToDeg(-m.omega.z()), 0.01);
  EXPECT_NEAR(radToDeg(c.camberGain), radToDeg(-m.omega.x()), 0.01);
  EXPECT_NEAR(c.halfTrackChange, m.contact.y(), 1e-4);
  EXPECT_NEAR(rig_->axle[0].rollCentre, m.rollCentre, 1e-4);
  EXPECT_NEAR(rig_->wheelbase, wheelbase, 1e-4);
  EXPECT_NEAR(rig_->antiDive, antiDive, 0.01);
  EXPECT_NEAR(rig_->brakeFront, 2500.0 / 4000.0, 1e-12);  // the wheels' brake torques, 2 x 2500 and 2 x 1500 N m
}

// Front-view roll centre by the textbook construction (Milliken, RCVD
// 17.2): the upright's instant centre is where the lower arm's line (from
// its pivot axis, cut at the ball joint's x, to the ball joint) meets the
// perpendicular to the strut through its top mount; the line from the
// contact point through it meets the centre plane at the roll centre.
//
// The construction is planar; this upright is not: as the wheel rises it
// also yaws (bump steer -33 deg/m) and pitches, and the contact point sits
// 18 mm behind the ball joint, the top mount 93 mm; the yaw alone moves the
// contact point sideways by Omega_z dx = 0.57 x 0.018 = 0.010 m per m, 13 %
// of its lateral rate, 11 mm of roll-centre height. The construction sits
// about 20 mm above the 3D answer (the velocity analysis above, 0.1 mm); 25
// mm is the tolerance of this check of its sense, not of its precision.
TEST_F(KcRig, FrontRollCentreIsNearTheFrontViewConstruction) {
  auto frontView = [](const Vec3& p) { return Eigen::Vector2d(p.y(), p.z()); };
  auto cross2 = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
  const Vec3 f = point("LCA_F"), b = point("LCA_B"), ball = point("LCA_U"), top = point("STRUT_TOP");
  const Vec3 pivot = b + (f - b) * ((ball.x() - b.x()) / (f.x() - b.x()));
  const Eigen::Vector2d strut = frontView(point("STRUT_LOW") - top), perpendicular(-strut.y(), strut.x());
  // The lower arm's line p + t d meets the strut's perpendicular q + u e.
  const Eigen::Vector2d p = frontView(pivot), d = frontView(ball - pivot), q = frontView(top);
  const Eigen::Vector2d ic = p + d * (cross2(q - p, perpendicular) / cross2(d, perpendicular));
  const Eigen::Vector2d contact(point("SPINDLE_F").y(), 0.0);
  const double hand = contact.x() * ic.y() / (contact.x() - ic.x());  // the line's height at y = 0
  std::printf("hand (front view): instant centre y %.3f m, z %.3f m; roll centre %.1f mm; rig %.1f mm\n", ic.x(),
              ic.y(), 1000 * hand, 1000 * rig_->axle[0].rollCentre);
  EXPECT_NEAR(rig_->axle[0].rollCentre, hand, 0.025);
}

// A symmetric car, mirrored left to right: in parallel travel both wheels
// of an axle toe and camber alike (equal bump steer and camber gain); in
// roll one side bumps as the other rebounds, so the toe and the camber to
// the ground change equal and opposite (roll steer and roll camber of the
// two wheels opposite). Equal to the rig's differences' noise (1e-6).
TEST_F(KcRig, SymmetricCarIsSymmetric) {
  for (int l : {0, 2}) {
    const vehicle::KcCorner &L = rig_->corner[l], &R = rig_->corner[l + 1];
    std::printf("%s/%s: bump steer %.4f / %.4f deg/m, camber gain %.4f / %.4f deg/m, roll steer %.5f / %.5f, "
                "roll camber %.5f / %.5f deg/deg\n",
                vehicle::kCornerNames[l], vehicle::kCornerNames[l + 1], radToDeg(L.bumpSteer), radToDeg(R.bumpSteer),
                radToDeg(L.camberGain), radToDeg(R.camberGain), L.rollSteer, R.rollSteer, L.rollCamber, R.rollCamber);
    EXPECT_NEAR(L.bumpSteer, R.bumpSteer, 1e-6 + 1e-6 * std::abs(L.bumpSteer));
    EXPECT_NEAR(L.camberGain, R.camberGain, 1e-6 + 1e-6 * std::abs(L.camberGain));
    EXPECT_NEAR(L.rollSteer, -R.rollSteer, 1e-6);
    EXPECT_NEAR(L.rollCamber, -R.rollCamber, 1e-6);
    EXPECT_NEAR(L.wheelRate, R.wheelRate, 1e-6 * L.wheelRate);
  }
  // Roll steer of a wheel is its bump steer times its travel per radian of
  // roll (track / 2; left: rebound as the left side rises), to first order.
  for (int w = 0; w < 4; ++w) {
    const double side = w % 2 == 0 ? 1.0 : -1.0;
    const double expected = -side * 0.5 * rig_->axle[w / 2].track * rig_->corner[w].bumpSteer;
    EXPECT_NEAR(rig_->corner[w].rollSteer, expected, 1e-6) << vehicle::kCornerNames[w];
  }
  // The steering sweep: the left wheel's angle at +steer is the right's at -steer.
  const vehicle::KcTable& st = rig_->tables[2];
  const size_t n = st.columns[0].values.size();
  for (size_t i = 0; i < n; ++i)
    EXPECT_NEAR(st.columns[3].values[i], -st.columns[4].values[n - 1 - i], 1e-7);
}

// The curves: every sample finite, the swept variable through zero at the
// middle sample, the design numbers on the curves; the strut's motion ratio
// and the wheel rate it gives.
TEST_F(KcRig, CurvesCoverTheRangeAndPassThroughDesign) {
  ASSERT_EQ(rig_->tables.size(), 3u);
  EXPECT_GE(rig_->travelRange, 0.08 - 1e-12);
  for (const vehicle::KcTable& t : rig_->tables) {
    const size_t n = t.columns[0].values.size();
    ASSERT_EQ(n % 2, 1u) << t.name;
    EXPECT_NEAR(t.columns[0].values[n / 2], 0.0, 1e-12) << t.name;
    for (const vehicle::KcColumn& c : t.columns)
      for (double x : c.values) EXPECT_TRUE(std::isfinite(x)) << t.name << " " << c.name;
  }
  // At design the curves give the design numbers: the parallel table's
  // front roll centre at travel 0 is the axle's.
  const vehicle::KcTable& par = rig_->tables[0];
  for (const vehicle::KcColumn& c : par.columns) {
    if (c.name == "roll_centre_front") {
      EXPECT_NEAR(c.values[c.values.size() / 2], rig_->axle[0].rollCentre, 1e-9);
    }
  }
  // The strut compresses in bump (motion ratio between 0 and -1).
  ASSERT_EQ(rig_->corner[0].motionRatio.size(), 1u);
  EXPECT_LT(rig_->corner[0].motionRatio[0], 0);
  EXPECT_GT(rig_->corner[0].motionRatio[0], -1);
  // The wheel rate is the spring rate times the motion ratio squared, plus
  // the strut's force at design times d2L/ds2 (the motion ratio changes with
  // travel): 1.3 % here; 5 % bounds it.
  const double k = 369149.0, mr = rig_->corner[0].motionRatio[0];
  EXPECT_NEAR(rig_->corner[0].wheelRate, k * mr * mr, 0.05 * k * mr * mr);
}

TEST(KcRigInput, RefusesAVehicleWithoutALinkageToSweep) {
  vehicle::Vehicle v = vehicle::buildVehicle(
      vehicle::loadVehicleFile(std::string(BDFCAR_SOURCE_DIR) + "/assets/vehicles/sedan.toml"));
  v.fidelity = vehicle::Fidelity::Kinematic;
  EXPECT_THROW(vehicle::runKcRig(v), mb::ModelError);
}

}  // namespace
}  // namespace bdfcar
