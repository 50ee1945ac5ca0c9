#include "render/synthetic_drive.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace bdfcar::render {
namespace {

using Eigen::Vector3d;
using vehicle::LinkKind;

constexpr double kRideHeight = 0.5128;           // chassis origin above ground (docs/reference-vehicle.md 10)
constexpr double kWheelbase = 2.46, kRadius = 0.3099;
constexpr double kSteeringRatio = 2.2;           // pinion / road-wheel angle (docs/reference-vehicle.md 6)
constexpr double kRollPerAccel = 0.0045;         // rad of body roll per m/s^2 of lateral acceleration

struct Member {
  Vector3d chassisEnd, uprightEnd;  // left side, chassis frame (docs/reference-vehicle.md 4.1, 5.1)
  LinkKind kind;
  double radius;
};

// Left-side members of the front MacPherson strut and the rear multi-link.
const Member kFront[] = {
    {{1.470, 0.520, -0.366}, {1.22835, 0.94058, -0.38403}, LinkKind::Arm, 0.02},
    {{0.950, 0.507, -0.347}, {1.22835, 0.94058, -0.38403}, LinkKind::Arm, 0.02},
    {{1.135, 0.785, 0.369}, {1.17597, 0.85329, 0.03845}, LinkKind::Strut, 0.035},
    {{0.950, 0.520, -0.269}, {1.01262, 0.89495, -0.22605}, LinkKind::TieRod, 0.012}};
const Member kRear[] = {
    {{-1.190, 0.547, -0.128}, {-1.194, 0.864, -0.059}, LinkKind::Arm, 0.018},
    {{-1.407, 0.508, -0.148}, {-1.194, 0.864, -0.059}, LinkKind::Arm, 0.018},
    {{-1.214, 0.338, -0.343}, {-1.221, 0.842, -0.303}, LinkKind::Link, 0.015},
    {{-0.527, 0.599, -0.282}, {-1.250, 0.864, -0.366}, LinkKind::Link, 0.025},
    {{-1.507, 0.320, -0.326}, {-1.394, 0.862, -0.266}, LinkKind::TieRod, 0.012},
    {{-1.069, 0.641, -0.100}, {-1.069, 0.669, -0.374}, LinkKind::Spring, 0.045}};
const Vector3d kSpindle[4] = {{1.21, 1.10, -0.236}, {1.21, -1.10, -0.236}, {-1.25, 0.95, -0.21}, {-1.25, -0.95, -0.21}};

Vector3d mirrored(const Vector3d& p, bool right) { return right ? Vector3d(p.x(), -p.y(), p.z()) : p; }

// Reference line and its heading at x, from central differences.
void pathAt(const scenario::Iso3888Course& c, double x, double& y, double& heading) {
  const double h = 0.05;
  y = c.referenceY(x);
  heading = std::atan2(c.referenceY(x + h) - c.referenceY(x - h), 2 * h);
}

}  // namespace

double syntheticDuration(const SyntheticDrive& d) { return (d.course.endX - d.course.startX + d.leadIn + 20.0) / d.speed; }

// Kinematic bicycle along the reference line: heading from the path slope, yaw rate
// and lateral acceleration from its rate of change, Ackermann steer from the curvature.
SyntheticFrame syntheticLaneChange(const SyntheticDrive& d, double t) {
  const double x = d.course.startX - d.leadIn + d.speed * t, dt = 0.01;
  double y, psi, yAhead, psiAhead;
  pathAt(d.course, x, y, psi);
  pathAt(d.course, x + d.speed * dt, yAhead, psiAhead);
  const double yawRate = (psiAhead - psi) / dt, ay = d.speed * yawRate;
  const double steer = std::atan(kWheelbase * yawRate / d.speed);

  SyntheticFrame f;
  vehicle::VehicleView& v = f.view;
  v.time = t;
  v.chassis.position = Vector3d(x, y, d.groundZ + kRideHeight);
  v.chassis.rotation = Eigen::AngleAxisd(psi, Vector3d::UnitZ()) * Eigen::AngleAxisd(-kRollPerAccel * ay, Vector3d::UnitX());
  const Eigen::Matrix3d r = v.chassis.rotation.toRotationMatrix();
  const double spin = (x - (d.course.startX - d.leadIn)) / kRadius;
  for (int i = 0; i < 4; ++i) {
    vehicle::WheelView& w = v.wheels[i];
    // Wheels stay on the ground while the body rolls: keep the spindle height.
    Vector3d c = v.chassis.position + r * kSpindle[i];
    c.z() = d.groundZ + kRideHeight + kSpindle[i].z();
    const double delta = i < 2 ? steer : 0.0;
    w.pose.position = c;
    w.pose.rotation = Eigen::AngleAxisd(psi + delta, Vector3d::UnitZ()) * Eigen::AngleAxisd(spin, Vector3d::UnitY());
    w.contactPoint = Vector3d(c.x(), c.y(), d.groundZ);
    w.inContact = true;
    w.normalForce = 5900.0;
  }
  // Chassis ends ride with the body; upright ends turn with the wheel about its centre.
  auto addMembers = [&](const auto& members, int wheel, bool right) {
    const Eigen::Matrix3d steerRot =
        Eigen::AngleAxisd(wheel < 2 ? steer : 0.0, Vector3d::UnitZ()).toRotationMatrix();
    for (const Member& m : members) {
      vehicle::LinkSegment s;
      s.a = v.chassis.position + r * mirrored(m.chassisEnd, right);
      s.b = v.wheels[wheel].pose.position +
            Eigen::AngleAxisd(psi, Vector3d::UnitZ()) * (steerRot * (mirrored(m.uprightEnd, right) - kSpindle[wheel]));
      s.kind = m.kind;
      s.radius = m.radius;
      v.links.push_back(s);
    }
  };
  for (int i = 0; i < 4; ++i) {
    if (i < 2) addMembers(kFront, i, i == 1);
    else addMembers(kRear, i, i == 3);
  }
  vehicle::LinkSegment rack;
  rack.a = v.chassis.position + r * Vector3d(0.95, 0.52 - 0.1 * steer * kSteeringRatio, -0.269);
  rack.b = v.chassis.position + r * Vector3d(0.95, -0.52 - 0.1 * steer * kSteeringRatio, -0.269);
  rack.kind = LinkKind::Rack;
  rack.radius = 0.02;
  v.links.push_back(rack);

  vehicle::HudInfo& h = f.hud;
  h.time = t;
  h.speed = d.speed;
  h.steeringWheelAngle = steer * kSteeringRatio;
  h.lateralAcceleration = ay;
  h.yawRate = yawRate;
  h.realTimeFactor = 1.0;
  h.stepTime = 350e-6;
  h.throttle = 0.18;
  h.coneHits = 0;
  h.courseTime = x >= d.course.startX ? (std::min(x, d.course.endX) - d.course.startX) / d.speed : -1.0;
  h.message = "synthetic lane change (kinematic, no physics)";
  return f;
}

}  // namespace bdfcar::render
