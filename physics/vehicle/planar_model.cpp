#include "vehicle/planar_model.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "multibody/multibody_dae.h"
#include "terrain/terrain.h"
#include "tyre/tyre_model.h"
#include "vehicle/equilibrium.h"
#include "vehicle/mass_moments.h"
#include "vehicle/vehicle_forces.h"

namespace bdfcar::vehicle {

namespace {

using Eigen::VectorXd;


// The kinematic model at rest on level ground.
struct Rest {
  VectorXd q;
  EquilibriumReport report;
  std::array<tyre::TyreOutput, 4> tyres;
};

Rest restOnLevelGround(const Vehicle& kin) {
  const terrain::PlaneTerrain ground;
  mb::MultibodyDae dae(kin.model);
  VehicleForces forces(kin, ground);
  dae.addForceProvider(&forces);
  Rest r;
  r.q = designPositions(kin);
  std::string msg;
  if (!assemble(kin, dae, 0.0, r.q, msg)) throw mb::ModelError("planar model: " + msg);
  VectorXd lambda = VectorXd::Zero(kin.model.nc);
  r.report = settleStatic(kin, dae, forces, 0.0, r.q, lambda);
  if (!r.report.converged)
    throw mb::ModelError("planar model: the kinematic model has no static equilibrium: " + r.report.message);
  for (int w = 0; w < 4; ++w) r.tyres[w] = forces.outputs()[w].out;
  return r;
}

// Generalised force of corner w's springs on its travel coordinate at travel
// s and travel rate sd (rack centred): sum of F(L, L' sd) L'.
double travelForce(const mb::Model& m, int carrier, double s, double sd) {
  const mb::JointTable& table = m.tables[m.bodies[carrier].table];
  mb::SplineGrid::Sample sample;
  table.grid.eval(s, 0.0, sample);
  double Q = 0;
  for (const mb::SpringDamper& e : m.springs) {
    if (e.tableBody != carrier) continue;
    const double L = sample.f[e.tableComponent], dL = sample.grad[e.tableComponent][0];
    Q += e.force(L, dL * sd) * dL;
  }
  return Q;
}

// Contact point of wheel w (world) at the data's positions, for a tyre
// deflected by delta on level ground.
Vec3 contactPoint(const Vehicle& v, const mb::Data& d, int w, double delta) {
  const int sp = v.layout.wheels[w].spindle;
  const Vec3 n = d.R[sp].col(1);
  const Vec3 xc = n.cross(Vec3::UnitZ()).normalized();
  const Vec3 down = n.cross(xc);
  const Vec3 centre = mb::pointPosition(d, sp, v.model.bodies[sp].inChild.origin);
  return centre + (tyre::unloadedRadius(v.wheel(w).tyre) - delta) * down;
}

// A rigid pose in the base frame.
struct Frame {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
  Vec3 point(const Vec3& x) const { return R * x + p; }
  mb::JointFrame frame(const mb::JointFrame& f) const { return {point(f.origin), R * f.axes}; }
};

}  // namespace

PlanarDerivation derivePlanar(const Vehicle& linkage) {
  PlanarDerivation out;
  out.kinematic = deriveKinematic(linkage);
  const Vehicle& kin = out.kinematic.vehicle;
  const mb::Model& km = kin.model;
  const VehicleLayout& KL = kin.layout;
  const Rest rest = restOnLevelGround(kin);
  mb::Data d = mb::makeData(km);
  mb::updatePositions(km, rest.q, d);

  // The base frame: on the ground under the chassis frame, level, heading +x
  // (the rest pose is on level ground with zero heading).
  const Vec3 origin(d.p[KL.chassis].x(), d.p[KL.chassis].y(), 0.0);
  const Frame chassisInBase{d.R[KL.chassis], d.p[KL.chassis] - origin};
  auto inBase = [&](int body) { return Frame{d.R[body], d.p[body] - origin}; };

  PlanarLoads loads;
  std::array<Vec3, 4> contact;
  std::array<double, 4> rcHeight{};
  for (int w = 0; w < 4; ++w) {
    const int u = KL.wheels[w].carrier;
    const double s = rest.q(km.bodies[u].qIndex);
    out.staticTravel[w] = s;
    const double delta = rest.tyres[w].deflection;
    contact[w] = contactPoint(kin, d, w, delta) - origin;
    // Wheel rate and damping at the static travel, in series with the tyre.
    const double ds = 1e-4, rate = 0.05;
    out.wheelRate[w] = -(travelForce(km, u, s + ds, 0) - travelForce(km, u, s - ds, 0)) / (2 * ds);
    const double damping = -(travelForce(km, u, s, rate) - travelForce(km, u, s, -rate)) / (2 * rate);
    const double kt = tyre::verticalStiffness(kin.wheel(w).tyre);
    if (!(out.wheelRate[w] > 0))
      throw mb::ModelError(std::string("planar model: wheel ") + kCornerNames[w] + " has no spring rate at its static travel");
    const double series = kt / (out.wheelRate[w] + kt);
    loads.rate[w] = out.wheelRate[w] * series;
    loads.suspensionShare[w] = series;
    loads.staticTravel[w] = s;
    loads.damping[w] = damping * series * series;
    loads.staticLoad[w] = rest.report.wheelLoads[w];
    // Roll centre (instant-centre construction): the line through the contact
    // point perpendicular to its motion with travel meets the centre plane at
    // (t/2) dy/dz above the ground, y outward.
    VectorXd q = rest.q;
    mb::Data dp = mb::makeData(km), dm = mb::makeData(km);
    q(km.bodies[u].qIndex) = s + ds;
    mb::updatePositions(km, q, dp);
    q(km.bodies[u].qIndex) = s - ds;
    mb::updatePositions(km, q, dm);
    // The carrier's attitude relative to the chassis over travel (the
    // chassis is held): its rotation per metre, in the chassis frame.
    const Mat3 turn = (dp.R[KL.chassis].transpose() * dp.R[u]) * (dm.R[KL.chassis].transpose() * dm.R[u]).transpose();
    loads.turnPerTravel[w] = Vec3(turn(2, 1) - turn(1, 2), turn(0, 2) - turn(2, 0), turn(1, 0) - turn(0, 1)) / (4 * ds);
    const Vec3 rate3 = contactPoint(kin, dp, w, delta) - contactPoint(kin, dm, w, delta);
    const Vec3 chassisOffset = dp.p[KL.chassis] - dm.p[KL.chassis];  // zero: the chassis is held
    const Vec3 motion = chassisInBase.R.transpose() * (rate3 - chassisOffset);
    const double outward = contact[w].y() > chassisInBase.p.y() ? 1.0 : -1.0;
    rcHeight[w] = 0.5 * outward * motion.y() / motion.z();  // times the track below
  }
  loads.sprungRest = chassisInBase.R;
  for (int a = 0; a < 2; ++a) {
    const int l = 2 * a, r = 2 * a + 1;
    loads.track[a] = std::abs(contact[l].y() - contact[r].y());
    loads.rollCentreHeight[a] = 0.5 * (rcHeight[l] + rcHeight[r]) * loads.track[a];
  }
  const double xFront = 0.5 * (contact[0].x() + contact[1].x()), xRear = 0.5 * (contact[2].x() + contact[3].x());
  loads.wheelbase = xFront - xRear;

  // The sprung body: the kinematic chassis, rolling and pitching about the
  // roll axis under its centre of mass.
  const mb::Body& kch = km.bodies[KL.chassis];
  const Vec3 sprungCom = chassisInBase.point(kch.com);
  const double along = (sprungCom.x() - xRear) / loads.wheelbase;
  loads.axisHeight = loads.rollCentreHeight[1] + along * (loads.rollCentreHeight[0] - loads.rollCentreHeight[1]);
  const Vec3 axisPoint(sprungCom.x(), sprungCom.y(), loads.axisHeight);
  for (int w = 0; w < 4; ++w) {
    loads.basePoint[w] = Vec3(contact[w].x(), contact[w].y(), loads.axisHeight);
    loads.sprungPoint[w] = chassisInBase.R.transpose() * (loads.basePoint[w] - chassisInBase.p);
  }
  MassMoments all;
  for (size_t i = 0; i < km.bodies.size(); ++i) {
    const Frame f = inBase(static_cast<int>(i));
    all.add(km.bodies[i].mass, f.point(km.bodies[i].com), f.R * km.bodies[i].inertia * f.R.transpose());
  }
  loads.comInBase = all.com();

  // The base: the unsteered carriers, lumped.
  MassMoments base;
  for (int w = 0; w < 4; ++w) {
    if (out.kinematic.steered[w]) continue;
    const int u = KL.wheels[w].carrier;
    const Frame f = inBase(u);
    base.add(km.bodies[u].mass, f.point(km.bodies[u].com), f.R * km.bodies[u].inertia * f.R.transpose());
  }
  if (!(base.m > 0))
    throw mb::ModelError("planar model: every corner steers; the base needs an unsteered axle");

  Vehicle outV;
  outV.fidelity = Fidelity::Planar;
  outV.spec = kin.spec;
  std::vector<BodySpec> specs;
  mb::ModelBuilder mbld;
  VehicleLayout& L = outV.layout;

  mb::Body b;
  b.name = "base";
  b.mass = base.m;
  b.com = base.com();
  b.inertia = base.inertiaAtCom();
  b.parent = mb::kGround;
  b.joint = mb::JointType::Planar;
  b.jointName = "road_plane";
  L.base = mbld.addBody(b);
  BodySpec bs = kin.spec.bodies[KL.chassis];
  bs.name = b.name;
  bs.mass = b.mass;
  bs.com = b.com;
  bs.inertia = b.inertia;
  bs.joint.type = b.joint;
  specs.push_back(bs);

  mb::Body ch = kch;
  ch.parent = L.base;
  ch.joint = mb::JointType::Universal;
  ch.jointName = "roll_pitch";
  ch.inParent = mb::JointFrame{axisPoint, Mat3::Identity()};
  ch.inChild = mb::JointFrame{chassisInBase.R.transpose() * (axisPoint - chassisInBase.p), chassisInBase.R.transpose()};
  L.chassis = mbld.addBody(ch);
  BodySpec cs = kin.spec.bodies[KL.chassis];
  cs.joint.type = ch.joint;
  cs.joint.parent = b.name;
  specs.push_back(cs);

  mb::Body rack = km.bodies[KL.rack];
  rack.parent = L.base;
  rack.inParent = chassisInBase.frame(rack.inParent);
  L.rack = mbld.addBody(rack);
  specs.push_back(kin.spec.bodies[KL.rack]);
  addRackDriver(mbld, "rack_travel", L.rack);

  for (int w = 0; w < 4; ++w) {
    const int u = KL.wheels[w].carrier;
    mb::Body wheel = km.bodies[KL.wheels[w].spindle];
    if (out.kinematic.steered[w]) {
      // The carrier's table over the rack at the static travel, in the base frame.
      const mb::JointTable& kt = km.tables[km.bodies[u].table];
      const mb::GridAxis rackAxis = kt.grid.axisY();
      std::vector<std::vector<double>> samples(mb::JointTable::kPoseComponents, std::vector<double>(rackAxis.nodes));
      mb::SplineGrid::Sample sample;
      for (int j = 0; j < rackAxis.nodes; ++j) {
        kt.grid.eval(out.staticTravel[w], rackAxis.start + j * rackAxis.step, sample);
        const Vec3 p = chassisInBase.point(Vec3(sample.f[0], sample.f[1], sample.f[2]));
        for (int k = 0; k < 3; ++k) {
          samples[k][j] = p(k);
          samples[3 + k][j] = sample.f[3 + k];
        }
      }
      mb::JointTable table;
      table.rest = chassisInBase.R * kt.rest;
      table.grid = mb::SplineGrid(rackAxis, mb::GridAxis{0, 1, 1}, samples);
      mb::Body carrier = km.bodies[u];
      carrier.parent = L.base;
      carrier.joint = mb::JointType::Tabulated1;
      carrier.table = mbld.addTable(table);
      L.wheels[w].carrier = mbld.addBody(carrier);
      BodySpec sc = kin.spec.bodies[u];
      sc.joint.type = carrier.joint;
      sc.joint.parent = b.name;
      specs.push_back(sc);
      addRackDriver(mbld, std::string("rack_travel_") + kCornerNames[w], L.wheels[w].carrier);
      wheel.parent = L.wheels[w].carrier;
    } else {
      // On the base, where its carrier sits at rest.
      L.wheels[w].carrier = L.base;
      wheel.parent = L.base;
      wheel.inParent = inBase(u).frame(wheel.inParent);
    }
    L.wheels[w].spindle = mbld.addBody(wheel);
    L.wheels[w].spinSign = KL.wheels[w].spinSign;
    specs.push_back(kin.spec.bodies[KL.wheels[w].spindle]);
  }
  addEngine(mbld, outV.spec, L.chassis, ch.com);
  outV.spec.bodies = specs;
  outV.spec.springs.clear();
  L.springCorner.clear();  // the corner springs are PlanarLoads'
  L.wheelCentreAtDesign = KL.wheelCentreAtDesign;
  outV.model = mbld.build();
  indexDerivedLayout(outV, KL.rackAxisSign);
  {
    mb::Data dd = mb::makeData(outV.model);
    mb::updatePositions(outV.model, designPositions(outV), dd);
    for (int w = 0; w < 4; ++w) loads.restTravel[w] = wheelCentreTravel(outV, dd, w);
    // What the suspension view draws: no members here, so a post per corner
    // from the wheel centre (on the base) to the sprung body 0.6 m above it
    // at design; the body's roll and pitch show as the posts lean and stretch.
    const int ch = L.chassis;
    for (int w = 0; w < 4; ++w) {
      const int sp = L.wheels[w].spindle;
      const Vec3 centre = outV.model.bodies[sp].inChild.origin;
      const Vec3 top = dd.R[ch].transpose() * (mb::pointPosition(dd, sp, centre) + Vec3(0, 0, 0.6) - dd.p[ch]);
      L.links.push_back({ch, sp, top, centre, LinkKind::Strut});
    }
  }
  outV.planar = loads;
  out.sprungMass = kch.mass;
  out.sprungComHeight = sprungCom.z();
  // Each axle's roll stiffness: the suspension (with its anti-roll bars,
  // rate t^2 each) in series with the tyres. Without a bar this is the
  // corner springs' own, sum(rate) t^2 / 4; with one, the planar model adds
  // the difference as a bar on the corners' deflection (barRate).
  for (int a = 0; a < 2; ++a) {
    const double t2 = loads.track[a] * loads.track[a];
    const int l = 2 * a, r = 2 * a + 1;
    const double corners = (loads.rate[l] + loads.rate[r]) * 0.25 * t2;
    double bars = 0;
    for (const AntiRollBarSpec& bar : kin.spec.antiRollBars)
      if (bar.left / 2 == a) bars += bar.rate * t2;
    double axle = corners;
    if (bars > 0) {
      auto tyreRate = [&](int w) { return 1.0 / (1.0 / loads.rate[w] - 1.0 / out.wheelRate[w]); };
      const double suspension = (out.wheelRate[l] + out.wheelRate[r]) * 0.25 * t2 + bars;
      const double tyres = (tyreRate(l) + tyreRate(r)) * 0.25 * t2;
      axle = 1.0 / (1.0 / suspension + 1.0 / tyres);
      loads.barRate[a] = (axle - corners) / t2;
    }
    out.rollStiffness += axle;
  }
  outV.planar->barRate = loads.barRate;
  out.vehicle = std::move(outV);
  return out;
}

void setPlanarRollAxis(Vehicle& planar, double axisHeight) {
  PlanarLoads& P = *planar.planar;
  const double shift = axisHeight - P.axisHeight;
  // The roll centres move with it: the load the axis carries past the
  // springs is the roll centres' share (the total is the statics').
  for (double& h : P.rollCentreHeight) h += shift;
  mb::Body& sprung = planar.model.bodies[planar.layout.chassis];
  const Vec3 up = Vec3::UnitZ() * shift;  // in the base frame
  sprung.inParent.origin += up;
  sprung.inChild.origin += P.sprungRest.transpose() * up;
  mb::refreshJointFrames(planar.model, planar.layout.chassis);
  for (int w = 0; w < 4; ++w) {
    P.basePoint[w] += up;
    P.sprungPoint[w] += P.sprungRest.transpose() * up;
  }
  P.axisHeight = axisHeight;
}

void setPlanarGround(Vehicle& planar, double groundZ) {
  planar.model.bodies[planar.layout.base].inParent.origin.z() = groundZ;
}

std::string describePlanar(const PlanarDerivation& d) {
  std::ostringstream o;
  char buf[300];
  const Vehicle& v = d.vehicle;
  const PlanarLoads& P = *v.planar;
  std::snprintf(buf, sizeof buf, "planar model: %d coordinates, %d constraint equations (rack drivers), %d bodies\n",
                v.model.nv, v.model.nc, static_cast<int>(v.model.bodies.size()));
  o << buf;
  std::snprintf(buf, sizeof buf, "  sprung %.1f kg on a roll and pitch axis %.3f m above the ground; wheelbase %.3f m\n",
                d.sprungMass, P.axisHeight, P.wheelbase);
  o << buf;
  if (d.kinematicRollGradient != 0) {
    std::snprintf(buf, sizeof buf,
                  "  the axis identified from the kinematic rung's steady roll (%.3f deg per m/s^2 at 0.3 of the "
                  "limit); the instant centres' construction puts it at %.3f m\n",
                  d.kinematicRollGradient * 180.0 / M_PI, d.geometricAxisHeight);
    o << buf;
  }
  const char* axle[2] = {"front", "rear"};
  for (int a = 0; a < 2; ++a) {
    std::snprintf(buf, sizeof buf, "  %s: track %.3f m, roll centre %.3f m\n", axle[a], P.track[a], P.rollCentreHeight[a]);
    o << buf;
  }
  for (int w = 0; w < 4; ++w) {
    std::snprintf(buf, sizeof buf,
                  "  %s: static load %.0f N at travel %+.4f m, wheel rate %.0f N/m (%.0f N/m with the tyre), "
                  "damping %.0f N s/m\n",
                  kCornerNames[w], P.staticLoad[w], d.staticTravel[w], d.wheelRate[w], P.rate[w], P.damping[w]);
    o << buf;
  }
  // The linkage's kinematics the rung carries: per 10 mm of bump, the toe
  // (+ in: a left wheel turning right) and camber (+ top out) from the
  // carrier's rotation (a left wheel's spin axis points left: a turn about
  // +z toes it out, about +x tilts its top in).
  for (int w = 0; w < 4; ++w) {
    const double side = w % 2 == 0 ? 1.0 : -1.0, per10mm = 0.01 * 180.0 / M_PI;
    std::snprintf(buf, sizeof buf, "  %s: per 10 mm of bump, toe %+.3f deg, camber %+.3f deg (from the linkage's sweep)\n",
                  kCornerNames[w], -side * P.turnPerTravel[w].z() * per10mm, -side * P.turnPerTravel[w].x() * per10mm);
    o << buf;
  }
  // Steady roll at 0.5 g: the sprung weight's moment about the roll axis
  // against the springs less gravity's overturning stiffness.
  const double arm = d.sprungComHeight - P.axisHeight, g = 9.81;
  const double roll = d.sprungMass * 0.5 * g * arm / (d.rollStiffness - d.sprungMass * g * arm);
  std::snprintf(buf, sizeof buf, "  roll stiffness %.0f N m/rad: %.2f deg of roll at 0.5 g\n", d.rollStiffness,
                roll * 180.0 / M_PI);
  o << buf;
  return o.str();
}

}  // namespace bdfcar::vehicle
