#include "vehicle/vehicle_builder.h"

#include <map>

#include "multibody/model_error.h"
#include "vehicle/motion_ratio.h"

namespace bdfcar::vehicle {

namespace {

using mb::Pose;

Mat3 jointAxes(const JointSpec& j) {
  switch (j.type) {
    case mb::JointType::Revolute:
    case mb::JointType::Prismatic:
    case mb::JointType::Cylindrical: return mb::axesWithZ(j.axis);
    case mb::JointType::Universal: return mb::axesWithXY(j.axisParent, j.axisChild);
    default: return Mat3::Identity();
  }
}

}  // namespace

Vehicle buildVehicle(const VehicleSpec& spec) {
  Vehicle out;
  out.spec = spec;
  const VehicleSpec& s = out.spec;
  mb::ModelBuilder mbld;
  std::map<std::string, int> index;
  std::vector<Pose> pose;  // design pose of each body in the chassis frame V

  auto bodyIndex = [&](const std::string& name, const std::string& who) {
    const auto it = index.find(name);
    if (it == index.end()) throw mb::ModelError(who + ": unknown body '" + name + "'");
    return it->second;
  };

  for (size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySpec& b = s.bodies[i];
    mb::Body body;
    body.name = b.name;
    body.mass = b.mass;
    body.jointName = b.name + "_joint";
    body.joint = b.joint.type;
    Pose p;
    // The axle shaft is a rotor about the spin joint's axis (the body axes are parallel to V at design).
    for (const WheelSpec& w : s.wheels)
      if (w.spindle == b.name) {
        body.rotorInertia = w.spinInertia;
        body.rotorAxis = b.joint.axis;
      }
    if (i == 0) {
      // The chassis frame is V itself; its free joint starts at the world origin.
      body.com = b.com;
      body.parent = mb::kGround;
    } else {
      p.p = b.com;  // other bodies: frame at the centre of mass, axes parallel to V at design
      body.com = Vec3::Zero();
      body.parent = bodyIndex(b.joint.parent, "body '" + b.name + "'");
      const Mat3 axes = jointAxes(b.joint);
      body.inParent = mb::frameAt(pose[body.parent], b.joint.at, axes);
      body.inChild = mb::frameAt(p, b.joint.at, axes);
    }
    body.inertia = b.inertia;
    index[b.name] = mbld.addBody(body);
    pose.push_back(p);
  }

  VehicleLayout& L = out.layout;
  for (const CutJointSpec& c : s.cutJoints) {
    mb::CutJoint cut;
    cut.name = c.name;
    cut.type = c.kind == CutKind::Spherical ? mb::CutJointType::Spherical : mb::CutJointType::Distance;
    cut.bodyA = bodyIndex(c.bodyA, "cut joint '" + c.name + "'");
    cut.bodyB = bodyIndex(c.bodyB, "cut joint '" + c.name + "'");
    cut.pointA = c.pointA - pose[cut.bodyA].p;
    cut.pointB = c.pointB - pose[cut.bodyB].p;
    if (cut.type == mb::CutJointType::Distance) {
      cut.length = c.length > 0 ? c.length : (c.pointA - c.pointB).norm();
      L.links.push_back({cut.bodyA, cut.bodyB, cut.pointA, cut.pointB,
                         c.bodyA == s.steering.rack ? LinkKind::TieRod : LinkKind::Link});
    }
    mbld.addCutJoint(cut);
    L.cutJointEquations += cut.type == mb::CutJointType::Spherical ? 3 : 1;
  }

  // Steering: the rack's coordinate follows the driver (a rheonomic constraint).
  L.rack = bodyIndex(s.steering.rack, "steering");
  {
    const BodySpec& rb = s.bodies[L.rack];
    if (rb.joint.type != mb::JointType::Prismatic)
      throw mb::ModelError("steering: the rack '" + rb.name + "' must be on a prismatic joint");
    L.rackAxisSign = rb.joint.axis.y() >= 0 ? 1.0 : -1.0;
    if (std::abs(rb.joint.axis.y()) < 0.99)
      throw mb::ModelError("steering: the rack '" + rb.name + "' must slide along the chassis y axis");
    mb::CutJoint drv;
    drv.name = "rack_travel";
    drv.type = mb::CutJointType::Driver;
    drv.drivenBody = L.rack;
    mbld.addCutJoint(drv);
  }

  for (const SpringSpec& sp : s.springs) {
    mb::SpringDamper e;
    e.name = sp.name;
    e.bodyA = bodyIndex(sp.bodyA, "spring '" + sp.name + "'");
    e.bodyB = bodyIndex(sp.bodyB, "spring '" + sp.name + "'");
    e.pointA = sp.pointA - pose[e.bodyA].p;
    e.pointB = sp.pointB - pose[e.bodyB].p;
    e.freeLength = sp.freeLength;
    e.preload = sp.preload;
    e.spring = sp.spring;
    e.damper = sp.damper;
    e.bumpLength = sp.bumpLength;
    e.bumpStiffness = sp.bumpStiffness;
    e.reboundLength = sp.reboundLength;
    e.reboundStiffness = sp.reboundStiffness;
    mbld.addSpring(e);
    L.links.push_back({e.bodyA, e.bodyB, e.pointA, e.pointB, LinkKind::Spring});
  }

  addEngine(mbld, s, 0, s.bodies.front().com);
  out.model = mbld.build();
  const mb::Model& m = out.model;
  L.chassis = 0;
  L.rackQ = m.bodies[L.rack].qIndex;
  L.rackV = m.bodies[L.rack].vIndex;
  L.rackDriverSlot = 0;
  for (int w = 0; w < 4; ++w) {
    WheelLayout& wl = L.wheels[w];
    wl.spindle = bodyIndex(s.wheels[w].spindle, "wheel " + s.wheels[w].position);
    const BodySpec& sb = s.bodies[wl.spindle];
    if (sb.joint.type != mb::JointType::Revolute)
      throw mb::ModelError("wheel " + s.wheels[w].position + ": the spindle '" + sb.name + "' must be on a revolute joint");
    if (std::abs(std::abs(sb.joint.axis.y()) - 1.0) > 1e-6)
      throw mb::ModelError("wheel " + s.wheels[w].position + ": the spin axis must be the chassis y axis at design");
    wl.carrier = m.bodies[wl.spindle].parent;
    wl.spinV = m.bodies[wl.spindle].vIndex;
    wl.spinSign = sb.joint.axis.y() > 0 ? 1.0 : -1.0;
    ++L.spinCoordinates;
  }
  // Members drawn from each suspension body's joint to its other attachment points.
  indexEngine(out);
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    if (static_cast<int>(i) == L.rack || static_cast<int>(i) == L.engine) continue;
    bool isWheel = false;
    for (const WheelLayout& wl : L.wheels) isWheel |= wl.spindle == static_cast<int>(i);
    if (isWheel) continue;
    const Vec3 jointPoint = m.bodies[i].inChild.origin;
    auto add = [&](const Vec3& p) {
      if ((p - jointPoint).norm() > 0.02) L.links.push_back({static_cast<int>(i), static_cast<int>(i), jointPoint, p, LinkKind::Arm});
    };
    for (const mb::CutJoint& c : m.cutJoints) {
      if (c.bodyA == static_cast<int>(i) && c.type != mb::CutJointType::Driver) add(c.pointA);
      if (c.bodyB == static_cast<int>(i) && c.type != mb::CutJointType::Driver) add(c.pointB);
    }
    for (size_t k = i + 1; k < m.bodies.size(); ++k)
      if (m.bodies[k].parent == static_cast<int>(i)) add(m.bodies[k].inParent.origin);
  }
  indexSuspensionChannels(out);
  return out;
}

void addRackDriver(mb::ModelBuilder& builder, const std::string& name, int body, int coordinate) {
  mb::CutJoint drv;
  drv.name = name;
  drv.type = mb::CutJointType::Driver;
  drv.drivenBody = body;
  drv.drivenCoordinate = coordinate;
  builder.addCutJoint(drv);
}

void indexDerivedLayout(Vehicle& v, double rackAxisSign) {
  VehicleLayout& L = v.layout;
  L.rackQ = v.model.bodies[L.rack].qIndex;
  L.rackV = v.model.bodies[L.rack].vIndex;
  L.rackAxisSign = rackAxisSign;
  L.rackDriverSlot = 0;
  L.cutJointEquations = 0;
  L.spinCoordinates = 0;
  for (WheelLayout& wl : L.wheels) {
    wl.spinV = v.model.bodies[wl.spindle].vIndex;
    ++L.spinCoordinates;
  }
  indexEngine(v);
}

void addEngine(mb::ModelBuilder& builder, const VehicleSpec& spec, int chassis, const Vec3& com) {
  if (!spec.powertrain) return;
  mb::Body e;
  e.name = "engine";
  e.jointName = "crank";
  e.joint = mb::JointType::Revolute;
  e.parent = chassis;
  // Massless: the engine's mass is the chassis'. Its rotating parts are a
  // rotor about the crank axis (chassis x), through the chassis' centre of
  // mass; its body axes are the chassis' at zero crank angle.
  e.rotorInertia = spec.powertrain->engine.inertia;
  e.rotorAxis = Vec3::UnitX();
  const Mat3 axes = mb::axesWithZ(Vec3::UnitX());
  e.inParent = mb::JointFrame{com, axes};
  e.inChild = mb::JointFrame{Vec3::Zero(), axes};
  builder.addBody(e);
}

void indexEngine(Vehicle& v) {
  VehicleLayout& L = v.layout;
  L.engine = L.engineQ = L.engineV = -1;
  if (!v.spec.powertrain) return;
  for (size_t i = 0; i < v.model.bodies.size(); ++i)
    if (v.model.bodies[i].name == "engine" && v.model.bodies[i].jointName == "crank") {
      L.engine = static_cast<int>(i);
      L.engineQ = v.model.bodies[i].qIndex;
      L.engineV = v.model.bodies[i].vIndex;
    }
}

void setRackTravel(const Vehicle& v, Eigen::VectorXd& q, double x) {
  for (const mb::CutJoint& c : v.model.cutJoints)
    if (c.type == mb::CutJointType::Driver) q(v.model.bodies[c.drivenBody].qIndex + c.drivenCoordinate) = x;
}

double wheelCentreTravel(const Vehicle& v, const mb::Data& d, int w) {
  const int ch = v.layout.chassis;
  const Vec3 centre = d.R[ch].transpose() * (d.p[v.layout.wheels[w].spindle] - d.p[ch]);
  return centre.z() - v.layout.wheelCentreAtDesign[w].z();
}

double suspensionTravel(const Vehicle& v, const mb::Data& d, int w) {
  const double raw = wheelCentreTravel(v, d, w);
  if (!v.planar) return raw;
  const PlanarLoads& P = *v.planar;
  return P.restTravel[w] + P.suspensionShare[w] * (raw - P.restTravel[w]);
}

Eigen::VectorXd designPositions(const Vehicle& v) {
  Eigen::VectorXd q = mb::neutralPositions(v.model);
  if (v.model.bodies[0].joint == mb::JointType::Free) q(v.model.bodies[0].qIndex + 2) = v.spec.designHeight;
  return q;
}

}  // namespace bdfcar::vehicle
