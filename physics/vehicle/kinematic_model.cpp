#include "vehicle/kinematic_model.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "multibody/multibody_dae.h"
#include "vehicle/derivation_cache.h"
#include "vehicle/equilibrium.h"
#include "vehicle/linkage_sweep.h"
#include "vehicle/mass_moments.h"
#include "vehicle/motion_ratio.h"
#include "physics_sources_hash.h"  // generated (physics/vehicle/CMakeLists.txt)
#include "portable_math.h"

namespace bdfcar::vehicle {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Angles (psi, phi, theta) of M = Rz(psi) Rx(phi) Ry(theta).
Vec3 zxyAngles(const Mat3& M) {
  return Vec3(pm::atan2(-M(0, 1), M(1, 1)), pm::asin(std::clamp(M(2, 1), -1.0, 1.0)), pm::atan2(-M(2, 0), M(2, 2)));
}

// What the sweep gives one corner: per table component, the samples on the grid.
struct CornerTable {
  bool steered = false;
  std::vector<int> springs;  // linkage spring indices moving with this wheel
  std::vector<std::vector<double>> samples;
  Mat3 rest = Mat3::Identity();
};

struct Sweep {
  mb::GridAxis travel, rack;
  std::array<CornerTable, 4> corners;
  int configurations = 0;
};

Sweep sweepLinkage(const Vehicle& v, LinkageSweep& ls, const KinematicGrid& g, double travel,
                   const std::vector<MotionRatio>& ratios) {
  const mb::Model& m = v.model;
  Sweep out;
  out.travel = {-travel, 2 * travel / (g.travelNodes - 1), g.travelNodes};
  const double rackRange = std::max(1e-3, g.rackMargin * std::abs(v.spec.steering.rackTravelFull));
  out.rack = {-rackRange, 2 * rackRange / (g.rackNodes - 1), g.rackNodes};
  const int ns = out.travel.nodes, nr = out.rack.nodes;
  for (int w = 0; w < 4; ++w) {
    CornerTable& c = out.corners[w];
    for (size_t k = 0; k < ratios.size(); ++k)
      if (ratios[k].wheel == w) c.springs.push_back(static_cast<int>(k));
    if (6 + c.springs.size() > static_cast<size_t>(mb::SplineGrid::kMaxComponents))
      throw mb::ModelError(std::string("kinematic model: too many spring-dampers on wheel ") + kCornerNames[w]);
    c.samples.assign(6 + c.springs.size(), std::vector<double>(ns * nr));
  }
  // Rack rows from the centre outwards, travel from the centre outwards: each
  // solve starts from a neighbour's solution.
  std::vector<VectorXd> rowStart(nr);
  const int jc = nr / 2, ic = ns / 2;
  std::vector<int> rackOrder = {jc}, travelOrder = {ic};
  for (int k = 1; k <= std::max(jc, nr - 1 - jc); ++k) {
    if (jc + k < nr) rackOrder.push_back(jc + k);
    if (jc - k >= 0) rackOrder.push_back(jc - k);
  }
  std::array<Mat3, 4> rest;
  bool haveRest = false;
  for (int j : rackOrder) {
    const int jn = j == jc ? jc : (j > jc ? j - 1 : j + 1);
    VectorXd q = j == jc ? ls.design() : rowStart[jn];
    const double r = out.rack.start + j * out.rack.step;
    for (int dir : {+1, -1}) {
      VectorXd qi = dir > 0 ? q : rowStart[j];
      for (int i = ic; i >= 0 && i < ns; i += dir) {
        if (dir < 0 && i == ic) continue;
        const double s = out.travel.start + i * out.travel.step;
        if (!ls.solve(s, r, qi)) {
          char buf[200];
          std::snprintf(buf, sizeof buf, "the linkage cannot be assembled at wheel travel %.3f m, rack %.4f m", s, r);
          throw mb::ModelError(buf);
        }
        ++out.configurations;
        if (i == ic) rowStart[j] = qi;
        mb::Data& d = ls.at(qi);
        const Mat3 Rc = d.R[v.layout.chassis];
        const Vec3 pc = d.p[v.layout.chassis];
        if (!haveRest && i == ic && j == jc) {
          for (int w = 0; w < 4; ++w) rest[w] = Rc.transpose() * d.R[v.layout.wheels[w].carrier];
          haveRest = true;
        }
        for (int w = 0; w < 4; ++w) {
          CornerTable& c = out.corners[w];
          const int carrier = v.layout.wheels[w].carrier;
          const Vec3 t = Rc.transpose() * (d.p[carrier] - pc);
          const Vec3 a = zxyAngles(rest[w].transpose() * Rc.transpose() * d.R[carrier]);
          const int n = i + ns * j;
          for (int k = 0; k < 3; ++k) {
            c.samples[k][n] = t(k);
            c.samples[3 + k][n] = a(k);
          }
          for (size_t k = 0; k < c.springs.size(); ++k) {
            const mb::SpringDamper& e = m.springs[c.springs[k]];
            c.samples[6 + k][n] = (mb::pointPosition(d, e.bodyA, e.pointA) - mb::pointPosition(d, e.bodyB, e.pointB)).norm();
          }
        }
      }
    }
  }
  for (int w = 0; w < 4; ++w) {
    CornerTable& c = out.corners[w];
    c.rest = rest[w];
    // Steered: the carrier moves with the rack (more than a micrometre or microradian).
    double spread = 0;
    for (int k = 0; k < 6; ++k)
      for (int i = 0; i < ns; ++i)
        for (int j = 0; j < nr; ++j) spread = std::max(spread, std::abs(c.samples[k][i + ns * j] - c.samples[k][i + ns * jc]));
    c.steered = spread > 1e-6;
    if (!c.steered)
      for (auto& comp : c.samples) comp = std::vector<double>(comp.begin() + ns * jc, comp.begin() + ns * (jc + 1));
  }
  return out;
}

// Wheel w's travel at design in the linkage: the suspension bodies' mass
// times their centres' rise per metre of travel (sum m dz/ds, kg; all
// bodies but the chassis, the rack and the wheels, which the kinematic model
// keeps as they are), and the carrier's own rise per metre of travel; by
// central differences over +-1 um of travel on the sweep's rig.
struct TravelWeight {
  double links = 0, carrierRise = 0;
};
TravelWeight travelWeight(const Vehicle& v, LinkageSweep& ls, int w) {
  const mb::Model& m = v.model;
  const double h = 1e-6, rack = ls.design()(v.layout.rackQ);
  std::array<std::vector<double>, 2> z;
  for (int k = 0; k < 2; ++k) {
    std::array<double, 4> s{};
    s[w] = k == 0 ? h : -h;
    VectorXd q = ls.design();
    if (!ls.solve(s, rack, q))
      throw mb::ModelError(std::string("kinematic model: the linkage does not move wheel ") + kCornerNames[w] + " at design");
    const mb::Data& d = ls.at(q);
    for (size_t b = 0; b < m.bodies.size(); ++b) z[k].push_back(mb::pointPosition(d, static_cast<int>(b), m.bodies[b].com).z());
  }
  TravelWeight out;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const int b = static_cast<int>(i);
    bool wheel = false;
    for (const WheelLayout& wl : v.layout.wheels) wheel |= wl.spindle == b;
    if (wheel || b == v.layout.chassis || b == v.layout.rack) continue;
    const double rise = (z[0][i] - z[1][i]) / (2 * h);
    out.links += m.bodies[i].mass * rise;
    if (b == v.layout.wheels[w].carrier) out.carrierRise = rise;
  }
  return out;
}

// The kinematic model for given carrier masses; lumpedWeight: each corner's
// first spring's Parts::weight (N).
Vehicle buildKinematic(const Vehicle& link, const Sweep& sw, const VectorXd& design,
                       const std::array<double, 4>& carrierMass, const std::array<double, 4>& lumpedWeight = {}) {
  const mb::Model& lm = link.model;
  const VehicleLayout& LL = link.layout;
  mb::Data d = mb::makeData(lm);
  mb::updatePositions(lm, design, d);
  const Mat3 Rc = d.R[LL.chassis];
  const Vec3 pc = d.p[LL.chassis];
  auto inChassis = [&](int b, Vec3& com, Mat3& I) {
    const Mat3 R = Rc.transpose() * d.R[b];
    com = Rc.transpose() * (mb::pointPosition(d, b, lm.bodies[b].com) - pc);
    I = R * lm.bodies[b].inertia * R.transpose();
  };
  // The chassis: every linkage body but the wheels and the rack, less the carriers.
  MassMoments chassis;
  for (size_t i = 0; i < lm.bodies.size(); ++i) {
    const int b = static_cast<int>(i);
    bool wheel = false;
    for (const WheelLayout& w : LL.wheels) wheel |= w.spindle == b;
    if (wheel || b == LL.rack) continue;
    Vec3 com;
    Mat3 I;
    inChassis(b, com, I);
    chassis.add(lm.bodies[b].mass, com, I);
  }
  for (int w = 0; w < 4; ++w) {
    const int u = LL.wheels[w].carrier;
    Vec3 com;
    Mat3 I;
    inChassis(u, com, I);
    chassis.add(carrierMass[w], com, I * (carrierMass[w] / lm.bodies[u].mass), -1.0);
  }

  Vehicle out;
  out.spec = link.spec;
  out.spec.cutJoints.clear();
  out.fidelity = Fidelity::Kinematic;
  std::vector<BodySpec> specs;
  mb::ModelBuilder mbld;
  VehicleLayout& L = out.layout;

  mb::Body ch = lm.bodies[LL.chassis];
  ch.mass = chassis.m;
  ch.com = chassis.com();
  ch.inertia = chassis.inertiaAtCom();
  ch.inertia = 0.5 * (ch.inertia + ch.inertia.transpose());
  L.chassis = mbld.addBody(ch);
  BodySpec chs = link.spec.bodies[LL.chassis];
  chs.mass = ch.mass;
  chs.com = ch.com;
  chs.inertia = ch.inertia;
  specs.push_back(chs);

  mb::Body rack = lm.bodies[LL.rack];
  rack.parent = L.chassis;
  L.rack = mbld.addBody(rack);
  specs.push_back(link.spec.bodies[LL.rack]);
  addRackDriver(mbld, "rack_travel", L.rack);

  std::array<int, 4> carrierIndex{};
  for (int w = 0; w < 4; ++w) {
    const CornerTable& c = sw.corners[w];
    mb::JointTable table;
    table.rest = c.rest;
    table.grid = mb::SplineGrid(sw.travel, c.steered ? sw.rack : mb::GridAxis{0, 1, 1}, c.samples);
    const int u = LL.wheels[w].carrier;
    mb::Body carrier = lm.bodies[u];
    carrier.mass = carrierMass[w];
    carrier.inertia = lm.bodies[u].inertia * (carrierMass[w] / lm.bodies[u].mass);
    carrier.rotorInertia = 0;
    carrier.parent = L.chassis;
    carrier.joint = c.steered ? mb::JointType::Tabulated2 : mb::JointType::Tabulated1;
    carrier.jointName = carrier.name + "_travel";
    carrier.inParent = mb::JointFrame{};
    carrier.inChild = mb::JointFrame{};
    carrier.table = mbld.addTable(table);
    carrierIndex[w] = mbld.addBody(carrier);
    BodySpec cs = link.spec.bodies[u];
    cs.mass = carrier.mass;
    cs.inertia = cs.inertia * (carrierMass[w] / lm.bodies[u].mass);
    cs.joint.type = carrier.joint;
    cs.joint.parent = link.spec.bodies[LL.chassis].name;
    specs.push_back(cs);
    if (c.steered) {
      addRackDriver(mbld, std::string("rack_travel_") + kCornerNames[w], carrierIndex[w], 1);
    }
    mb::Body wheel = lm.bodies[LL.wheels[w].spindle];
    wheel.parent = carrierIndex[w];
    L.wheels[w].spindle = mbld.addBody(wheel);
    L.wheels[w].carrier = carrierIndex[w];
    L.wheels[w].spinSign = LL.wheels[w].spinSign;
    specs.push_back(link.spec.bodies[LL.wheels[w].spindle]);
    // Springs of this corner act through their tabulated lengths.
    for (size_t k = 0; k < c.springs.size(); ++k) {
      // What the suspension view draws of it: its chassis mount to its
      // mount on the carrier, or to the wheel centre where it bears on a
      // member this model has not kept (a lower arm).
      const mb::SpringDamper& drawn = lm.springs[c.springs[k]];
      const bool aOnChassis = drawn.bodyA == LL.chassis;
      if (aOnChassis || drawn.bodyB == LL.chassis) {
        const int other = aOnChassis ? drawn.bodyB : drawn.bodyA;
        const Vec3& mount = aOnChassis ? drawn.pointA : drawn.pointB;
        if (other == u)
          L.links.push_back({L.chassis, carrierIndex[w], mount, aOnChassis ? drawn.pointB : drawn.pointA, LinkKind::Spring});
        else
          L.links.push_back({L.chassis, L.wheels[w].spindle, mount, wheel.inChild.origin, LinkKind::Spring});
      }
      mb::SpringDamper e = lm.springs[c.springs[k]];
      e.bodyA = e.bodyB = mb::kGround;
      e.pointA = e.pointB = Vec3::Zero();
      e.tableBody = carrierIndex[w];
      e.tableComponent = 6 + static_cast<int>(k);
      if (k == 0) e.lumpedWeight = lumpedWeight[w];
      mbld.addSpring(e);
    }
  }
  addEngine(mbld, out.spec, L.chassis, ch.com);
  out.spec.bodies = specs;
  // Springs in the order the model holds them.
  out.spec.springs.clear();
  L.springCorner.clear();
  for (int w = 0; w < 4; ++w)
    for (int k : sw.corners[w].springs) {
      out.spec.springs.push_back(link.spec.springs[k]);
      L.springCorner.push_back(w);
    }
  L.wheelCentreAtDesign = LL.wheelCentreAtDesign;
  out.model = mbld.build();
  indexDerivedLayout(out, LL.rackAxisSign);
  return out;
}

// Generalised mass of wheel w's travel in the kinematic model at design.
double kinematicTravelMass(const Vehicle& k, int w) {
  mb::Data d = mb::makeData(k.model);
  const VectorXd q = designPositions(k);
  mb::updatePositions(k.model, q, d);
  MatrixXd M(k.model.nv, k.model.nv);
  mb::massMatrix(k.model, d, M);
  const int vi = k.model.bodies[k.layout.wheels[w].carrier].vIndex;
  return M(vi, vi);
}

// Wheel centre and spin axis (chassis frame) of wheel w in a model's data.
void wheelPose(const Vehicle& v, const mb::Data& d, int w, Vec3& centre, Vec3& axis) {
  const int sp = v.layout.wheels[w].spindle, ch = v.layout.chassis;
  const Mat3 Rt = d.R[ch].transpose();
  centre = Rt * (mb::pointPosition(d, sp, v.model.bodies[sp].inChild.origin) - d.p[ch]);
  axis = Rt * d.R[sp].col(1);
}

KinematicCheck checkAgainstLinkage(const Vehicle& link, LinkageSweep& ls, const Vehicle& kin, const Sweep& sw) {
  KinematicCheck c;
  c.travelRange = sw.travel.end();
  c.rackRange = sw.rack.end();
  mb::Data dk = mb::makeData(kin.model);
  VectorXd ql = ls.design();
  // Midpoints between the nodes (every other cell in each direction), where
  // interpolation errs most.
  for (int j = 0; j + 1 < sw.rack.nodes; j += 2) {
    const double r = sw.rack.start + (j + 0.5) * sw.rack.step;
    ql = ls.design();
    for (int i = sw.travel.nodes / 2; i + 1 < sw.travel.nodes; i += 2) {
      const double s = sw.travel.start + (i + 0.5) * sw.travel.step;
      if (!ls.solve(s, r, ql)) continue;
      ++c.points;
      mb::Data& dl = ls.at(ql);
      VectorXd qk = designPositions(kin);
      qk(kin.layout.rackQ) = r;
      for (int w = 0; w < 4; ++w) {
        const mb::Body& cb = kin.model.bodies[kin.layout.wheels[w].carrier];
        qk(cb.qIndex) = s;
        if (cb.nq > 1) qk(cb.qIndex + 1) = r;
      }
      mb::updatePositions(kin.model, qk, dk);
      for (int w = 0; w < 4; ++w) {
        Vec3 cl, al, ck, ak;
        wheelPose(link, dl, w, cl, al);
        wheelPose(kin, dk, w, ck, ak);
        // Both models put the chassis at the same design pose.
        c.wheelCentre = std::max(c.wheelCentre, (cl - ck).norm());
        c.camber = std::max(c.camber, std::abs(pm::asin(al.z()) - pm::asin(ak.z())));
        c.toe = std::max(c.toe, std::abs(pm::atan2(-al.x(), al.y()) - pm::atan2(-ak.x(), ak.y())));
      }
    }
  }
  return c;
}

// The cache entry (derivation_cache.h): the sweep and the check's figures.
constexpr std::uint32_t kCacheFormat = 1;

// Keyed by the vehicle, the grid and the code that sweeps it (the physics
// sources and the build flavour, cmake/source_fingerprint.cmake): an entry
// that an older build or the other flavour wrote holds other last bits.
std::uint64_t cacheKey(const Vehicle& linkage, const KinematicGrid& g) {
  ByteBuffer k;
  k.put(derivationFingerprint(linkage));
  k.put(kCacheFormat);
  k.put(static_cast<std::uint64_t>(BDFCAR_PHYSICS_SOURCES_HASH));
  k.put(g.travelNodes);
  k.put(g.rackNodes);
  k.put(g.travel);
  k.put(g.rackMargin);
  return hashBytes(k.bytes);
}

ByteBuffer storeSweep(const Sweep& sw, const KinematicCheck& c) {
  ByteBuffer b;
  for (const mb::GridAxis& a : {sw.travel, sw.rack}) {
    b.put(a.start);
    b.put(a.step);
    b.put(a.nodes);
  }
  b.put(sw.configurations);
  for (const CornerTable& t : sw.corners) {
    b.put(static_cast<std::uint8_t>(t.steered));
    b.put(static_cast<std::uint64_t>(t.springs.size()));
    for (int k : t.springs) b.put(k);
    b.put(t.rest);
    b.put(static_cast<std::uint64_t>(t.samples.size()));
    for (const std::vector<double>& comp : t.samples) b.putDoubles(comp);
  }
  b.put(c);
  return b;
}

bool loadSweep(ByteBuffer b, Sweep& sw, KinematicCheck& c) {
  bool ok = true;
  for (mb::GridAxis* a : {&sw.travel, &sw.rack}) ok = ok && b.get(a->start) && b.get(a->step) && b.get(a->nodes);
  ok = ok && b.get(sw.configurations);
  for (CornerTable& t : sw.corners) {
    std::uint8_t steered = 0;
    std::uint64_t n = 0;
    ok = ok && b.get(steered) && b.get(n) && n < 64;
    if (!ok) return false;
    t.steered = steered != 0;
    t.springs.resize(n);
    for (int& k : t.springs) ok = ok && b.get(k);
    ok = ok && b.get(t.rest) && b.get(n) && n <= static_cast<std::uint64_t>(mb::SplineGrid::kMaxComponents);
    if (!ok) return false;
    t.samples.resize(n);
    for (std::vector<double>& comp : t.samples) ok = ok && b.getDoubles(comp);
  }
  return ok && b.get(c) && b.atEnd();
}

}  // namespace

KinematicDerivation deriveKinematic(const Vehicle& linkage, const KinematicGrid& grid) {
  if (linkage.fidelity != Fidelity::Linkage) throw mb::ModelError("kinematic model: derived from a linkage model only");
  const std::vector<MotionRatio> ratios = motionRatios(linkage);
  for (const MotionRatio& r : ratios)
    if (r.wheel < 0)
      throw mb::ModelError("kinematic model: spring-damper '" + r.element + "' does not move with one wheel");
  LinkageSweep ls(linkage);
  KinematicDerivation out;
  const std::uint64_t key = cacheKey(linkage, grid);
  Sweep sw;
  KinematicCheck cachedCheck;
  if (std::optional<ByteBuffer> entry = readDerivationCache("kinematic", key))
    out.fromCache = loadSweep(std::move(*entry), sw, cachedCheck);
  // The widest travel the linkage reaches, from the grid's down to a quarter of it.
  double travel = grid.travel;
  for (int attempt = 0; !out.fromCache; ++attempt) {
    try {
      sw = sweepLinkage(linkage, ls, grid, travel, ratios);
      break;
    } catch (const mb::ModelError& e) {
      if (attempt == 4) throw mb::ModelError(std::string("kinematic model: ") + e.what());
      travel *= 0.75;
    }
  }
  out.sweepConfigurations = sw.configurations;
  // Carrier masses from the linkage's generalised mass along each travel.
  mb::MultibodyDae dae(linkage.model);
  MatrixXd M(linkage.model.nv, linkage.model.nv);
  dae.massMatrix(0, ls.design(), M);
  std::array<double, 4> trial{}, doubled{};
  for (int w = 0; w < 4; ++w) {
    const VectorXd n = ls.travelDirection(ls.design(), w);
    out.linkageTravelMass[w] = n.dot(M * n);
    trial[w] = linkage.model.bodies[linkage.layout.wheels[w].carrier].mass;
    doubled[w] = 2 * trial[w];
    out.steered[w] = sw.corners[w].steered;
  }
  // The carrier's share is linear in its mass: two trial builds give it.
  const Vehicle k1 = buildKinematic(linkage, sw, ls.design(), trial);
  const Vehicle k2 = buildKinematic(linkage, sw, ls.design(), doubled);
  for (int w = 0; w < 4; ++w) {
    const double m1 = kinematicTravelMass(k1, w), m2 = kinematicTravelMass(k2, w);
    const double perKg = (m2 - m1) / trial[w];
    const double others = m1 - perKg * trial[w];
    out.carrierMass[w] = (out.linkageTravelMass[w] - others) / perKg;
    if (!(out.carrierMass[w] > 0))
      throw mb::ModelError(std::string("kinematic model: wheel ") + kCornerNames[w] +
                           ": the linkage's travel inertia is below the wheel's own");
  }
  // The links' weight along each travel. In the linkage gravity does
  // g sum m dz/ds of work per metre of travel on the suspension's bodies;
  // in this model only the carrier's mass moves with the travel (the rest
  // is lumped into the chassis, and the carrier's mass is what makes the
  // travel's inertia the linkage's, sum m (dz/ds)^2, not its weight). The
  // difference would rest on the springs (the sedan's rear 39 N along
  // travel: 0.6 mm lower, 0.2 mrad of pitch at rest); it goes on each
  // corner's first spring as a force of its own (exact at design).
  std::array<double, 4> lumped{};
  const double g = -linkage.model.gravity.z();
  for (int w = 0; w < 4; ++w) {
    const std::vector<int>& springs = sw.corners[w].springs;
    if (springs.empty()) continue;
    const double ratio = ratios[springs.front()].ratio;  // dL/ds of that spring at design
    if (!(std::abs(ratio) > 1e-6)) continue;
    const TravelWeight tw = travelWeight(linkage, ls, w);
    lumped[w] = -g * (tw.links - out.carrierMass[w] * tw.carrierRise) / ratio;
  }
  out.vehicle = buildKinematic(linkage, sw, ls.design(), out.carrierMass, lumped);
  if (out.fromCache) {
    out.check = cachedCheck;
  } else {
    out.check = checkAgainstLinkage(linkage, ls, out.vehicle, sw);
    writeDerivationCache("kinematic", key, storeSweep(sw, out.check));
  }
  out.cacheFile = derivationCachePath("kinematic", key);
  return out;
}

std::string describeKinematic(const KinematicDerivation& d) {
  std::ostringstream o;
  char buf[300];
  const Vehicle& v = d.vehicle;
  std::snprintf(buf, sizeof buf, "kinematic model: %d coordinates, %d constraint equations (rack drivers), %d bodies\n",
                v.model.nv, v.model.nc, static_cast<int>(v.model.bodies.size()));
  o << buf;
  std::snprintf(buf, sizeof buf, "  tables: wheel travel +-%.3f m, rack +-%.4f m, from %d linkage configurations%s\n",
                d.check.travelRange, d.check.rackRange, d.sweepConfigurations,
                d.fromCache ? " (read from the cache)" : "");
  o << buf;
  for (int w = 0; w < 4; ++w) {
    std::snprintf(buf, sizeof buf, "  %s: %s, carrier %.2f kg (linkage travel inertia %.2f kg)\n", kCornerNames[w],
                  d.steered[w] ? "travel x rack" : "travel", d.carrierMass[w], d.linkageTravelMass[w]);
    o << buf;
  }
  std::snprintf(buf, sizeof buf, "  chassis: %.1f kg (total %.1f kg, as the linkage)\n", v.model.bodies[0].mass,
                v.model.totalMass());
  o << buf;
  std::snprintf(buf, sizeof buf,
                "  check against the linkage at %d configurations between the nodes: wheel centre %.2g m, "
                "camber %.2g rad, toe/steer %.2g rad\n",
                d.check.points, d.check.wheelCentre, d.check.camber, d.check.toe);
  o << buf;
  return o.str();
}

}  // namespace bdfcar::vehicle
