#include "vehicle/vehicle_sample.h"

#include <algorithm>
#include <cmath>

#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/kinematics.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

VehicleSample sampleVehicle(const Vehicle& v, mb::MultibodyDae& dae, VehicleForces& forces,
                            const integ::SolutionPoint& s, bool evaluated) {
  const mb::Model& m = v.model;
  mb::Data& d = dae.data();
  if (!evaluated) {
    mb::sampleDrivers(m, d, s.t);
    mb::updatePositions(m, s.q, d);
    mb::updateVelocities(m, s.v, d);
    mb::updateAccelerations(m, s.a, d);
    mb::clearForces(m, d);
    d.jointForce.setZero();
    forces.apply(m, d, s.t);  // tyre outputs at this state (transient slips as accepted)
  }

  VehicleSample out;
  out.t = s.t;
  const int ch = v.layout.chassis;
  const Mat3& R = d.R[ch];
  const Vec3 c = m.bodies[ch].com;
  out.com = mb::pointPosition(d, ch, c);
  out.chassisOrigin = d.p[ch];
  out.chassisRotation = R;
  out.roll = pm::atan2(R(2, 1), R(2, 2));
  out.pitch = -pm::asin(std::clamp(R(2, 0), -1.0, 1.0));
  out.yaw = pm::atan2(R(1, 0), R(0, 0));
  const Vec3 vel = mb::pointVelocity(d, ch, c), acc = mb::pointAcceleration(d, ch, c);
  const Vec3 vb = R.transpose() * vel, ab = R.transpose() * acc;
  out.vx = vb.x();
  out.vy = vb.y();
  out.speed = vel.norm();
  out.ax = ab.x();
  out.ay = ab.y();
  out.yawRate = d.vel[ch].tail<3>().z();
  out.rollRate = d.vel[ch].tail<3>().x();
  out.pitchRate = d.vel[ch].tail<3>().y();
  out.sideslip = pm::atan2(out.vy, out.vx);
  // Ground-plane component normal to the heading.
  Vec3 heading(R(0, 0), R(1, 0), 0.0);
  if (heading.norm() > 1e-9) {
    heading.normalize();
    out.ayHorizontal = acc.dot(Vec3(-heading.y(), heading.x(), 0.0));
  }
  out.rack = v.layout.rackAxisSign * s.q(v.layout.rackQ);
  for (int w = 0; w < 4; ++w) {
    const WheelContact& wc = forces.wheels()[w];
    const WheelOutput& wo = forces.outputs()[w];
    out.Fz[w] = wo.out.Fz;
    out.Fx[w] = wo.out.Fx;
    out.Fy[w] = wo.out.Fy;
    out.alpha[w] = wo.out.slipAngle();
    out.kappa[w] = wo.out.kappa;
    out.inContact[w] = wo.out.inContact;
    out.spinRate[w] = wo.spinRate;
    out.driveTorque[w] = wc.driveTorque;
    // Road-wheel steer: heading of the spin axis relative to the chassis, + = left.
    const Vec3 n = R.transpose() * d.R[v.layout.wheels[w].spindle].col(1);
    out.steerAngle[w] = pm::atan2(-n.x(), n.y());
    // Camber and toe by the SAE convention: + when the wheel's top leans
    // out, + when its front points in (left is +y, right is -y).
    const double outward = w % 2 == 0 ? 1.0 : -1.0;
    out.camber[w] = -outward * pm::asin(std::clamp(n.z(), -1.0, 1.0));
    out.toe[w] = -outward * out.steerAngle[w];
    out.Mz[w] = wo.out.Mz;
    out.travel[w] = suspensionTravel(v, d, w);
    if (v.planar) {
      out.springForce[w] = wo.cornerSpring;
      out.damperForce[w] = wo.cornerDamper;
    }
  }
  for (size_t k = 0; k < m.springs.size(); ++k) {
    const int w = k < v.layout.springCorner.size() ? v.layout.springCorner[k] : -1;
    if (w < 0) continue;
    const mb::SpringDamper::Parts p = m.springs[k].parts(d.springLength[k], d.springLengthRate[k]);
    out.springForce[w] += p.spring;
    out.damperForce[w] += p.damper;
    out.stopForce[w] += p.stop;
  }
  // The rack's driver, and in a kinematic model the steered corners' rack
  // travel drivers too: together they carry the rack force.
  out.rackForce = 0;
  for (const mb::CutJoint& cj : m.cutJoints)
    if (cj.type == mb::CutJointType::Driver) out.rackForce += v.layout.rackAxisSign * s.lambda(cj.row);
  return out;
}

VehicleView viewVehicle(const Vehicle& v, const mb::MultibodyDae& dae, const VehicleForces& forces, double t) {
  const mb::Data& d = dae.data();
  VehicleView view;
  view.time = t;
  view.chassis.position = d.p[v.layout.chassis];
  view.chassis.rotation = Eigen::Quaterniond(d.R[v.layout.chassis]);
  for (int w = 0; w < 4; ++w) {
    const int b = v.layout.wheels[w].spindle;
    WheelView& wv = view.wheels[w];
    wv.pose.position = d.p[b];
    wv.pose.rotation = Eigen::Quaterniond(d.R[b]);
    wv.radius = tyre::unloadedRadius(v.wheel(w).tyre);
    wv.width = tyre::width(v.wheel(w).tyre);
    wv.contactPoint = forces.outputs()[w].out.contactPoint;
    wv.normalForce = forces.outputs()[w].out.Fz;
    wv.inContact = forces.outputs()[w].out.inContact;
  }
  for (const LinkDrawing& l : v.layout.links) {
    LinkSegment s;
    s.a = mb::pointPosition(d, l.bodyA, l.pointA);
    s.b = mb::pointPosition(d, l.bodyB, l.pointB);
    s.kind = l.kind;
    s.radius = l.kind == LinkKind::Spring ? 0.035 : 0.015;
    view.links.push_back(s);
  }
  return view;
}

}  // namespace bdfcar::vehicle
