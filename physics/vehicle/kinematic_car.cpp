#include "vehicle/kinematic_car.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "multibody/joint.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "autodiff.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

namespace {

[[noreturn]] void refuse(const std::string& what) { throw mb::ModelError("closed-form kinematic car: " + what); }

bool atOrigin(const mb::JointFrame& f) { return f.origin.isZero() && f.axes.isIdentity(); }

// Inertia of a mass m at offset d (parallel axes).
Mat3 pointInertia(double m, const Vec3& d) { return m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()); }

}  // namespace

KinematicCar::KinematicCar(const Vehicle& k, const terrain::Terrain& terrain, const TerrainContactOptions& options)
    : ClosedFormCar(k, terrain, options), steeringTime_(std::numeric_limits<double>::quiet_NaN()) {
  if (k.fidelity != Fidelity::Kinematic) refuse("the vehicle is not a kinematic model");
  const mb::Model& m = k.model;
  const VehicleLayout& L = k.layout;
  n_ = kCoordinates;
  chassisJoint_ = mb::JointType::Free;  // the chassis'
  chassisQ_ = 7;
  chassisV_ = 6;
  nq_ = kPositions;
  fastColumns_ = {SpinV, SpinV + 1, SpinV + 2, SpinV + 3};
  gravity_ = m.gravity;
  for (const mb::CutJoint& c : m.cutJoints)
    if (c.type != mb::CutJointType::Driver) refuse("cut joint '" + c.name + "' is not a rack driver");
  auto driven = [&](int vIndex) {
    for (const auto& d : drivenCoordinates_)
      if (d.second == vIndex) return true;
    return false;
  };

  const mb::Body& ch = m.bodies[L.chassis];
  if (L.chassis != 0 || ch.joint != mb::JointType::Free || ch.parent != mb::kGround || !atOrigin(ch.inChild) ||
      !atOrigin(ch.inParent))
    refuse("the chassis is not on a free joint of the world");
  chassisMass_ = ch.mass;
  chassisCom_ = ch.com;
  chassisInertia_ = fullInertia(ch);

  // Positions relative to the chassis at design (the chassis unrotated).
  mb::Data d = mb::makeData(m);
  Eigen::VectorXd q0 = designPositions(k);
  mb::updatePositions(m, q0, d);
  const Vec3 origin = d.p[L.chassis];
  std::vector<bool> known(m.bodies.size(), false);
  known[L.chassis] = true;

  if (L.rack >= 0) {
    const mb::Body& r = m.bodies[L.rack];
    if (r.parent != L.chassis || r.joint != mb::JointType::Prismatic || !driven(r.vIndex))
      refuse("the rack does not slide on the chassis, driven by the steering");
    rackMass_ = r.mass;
    rackCom0_ = d.R[L.rack] * r.com + d.p[L.rack] - origin;
    rackInertia_ = d.R[L.rack] * fullInertia(r) * d.R[L.rack].transpose();
    Eigen::VectorXd q1 = q0;
    q1(r.qIndex) += 1.0;
    mb::updatePositions(m, q1, d);
    rackAxis_ = d.R[L.rack] * r.com + d.p[L.rack] - origin - rackCom0_;
    mb::updatePositions(m, q0, d);
    known[L.rack] = true;
  }
  if (L.engine >= 0) {
    // The crank: a massless rotor about the chassis' x axis (addEngine).
    const mb::Body& e = m.bodies[L.engine];
    if (e.parent != L.chassis || e.mass != 0 || !e.inertia.isZero() || !e.rotorAxis.isApprox(Vec3::UnitX()) ||
        !e.inParent.axes.col(2).isApprox(Vec3::UnitX()) || !e.inChild.axes.col(2).isApprox(Vec3::UnitX()))
      refuse("the engine is not a rotor about the chassis' x axis");
    engineInertia_ = e.rotorInertia;
    engineMultibodyQ_ = e.qIndex;
    engineMultibodyV_ = e.vIndex;
    n_ = kCoordinates + 1;
    nq_ = kPositions + 1;
    known[L.engine] = true;
  }

  for (int w = 0; w < 4; ++w) {
    const std::string name = std::string("wheel ") + kCornerNames[w];
    Corner& C = corners_[w];
    const int ci = L.wheels[w].carrier, si = L.wheels[w].spindle;
    const mb::Body& cb = m.bodies[ci];
    const mb::Body& wb = m.bodies[si];
    C.steered = cb.joint == mb::JointType::Tabulated2;
    if (cb.parent != L.chassis || (cb.joint != mb::JointType::Tabulated1 && !C.steered) || cb.table < 0 ||
        !atOrigin(cb.inParent) || !atOrigin(cb.inChild) || (C.steered && !driven(cb.vIndex + 1)))
      refuse(name + "'s carrier is not on a table of the chassis");
    if (wb.parent != ci) refuse(name + " is not on its carrier");
    const SpinJoint spin = spinJoint(wb, name, "closed-form kinematic car");
    C.table = &m.tables[cb.table].grid;
    C.rest = m.tables[cb.table].rest;
    C.spinInertia = spin.inertia;
    C.spinSign = spin.sign;
    C.travelQ = cb.qIndex;
    C.travelV = cb.vIndex;
    C.spinQ = wb.qIndex;
    C.spinV = wb.vIndex;
    // The wheel in the carrier's frame (constant: it is symmetric about its axis).
    const Mat3 Rc = d.R[ci].transpose();
    const Mat3 Rw = Rc * d.R[si];
    C.centre = Rc * (d.p[si] - d.p[ci]);
    C.axisY = Rw.col(1);
    const Vec3 wheelCom = C.centre + Rw * wb.com;
    C.mass = cb.mass + wb.mass;
    if (!(C.mass > 0)) refuse(name + "'s corner has no mass");
    C.com = (cb.mass * cb.com + wb.mass * wheelCom) / C.mass;
    C.inertia = fullInertia(cb) + pointInertia(cb.mass, cb.com - C.com) + Rw * spin.symmetric * Rw.transpose() +
                pointInertia(wb.mass, wheelCom - C.com);
    known[ci] = known[si] = true;
  }
  for (size_t i = 0; i < m.springs.size(); ++i) {
    const mb::SpringDamper& s = m.springs[i];
    int corner = -1;
    for (int w = 0; w < 4; ++w)
      if (s.tableBody >= 0 && s.tableBody == L.wheels[w].carrier) corner = w;
    if (corner < 0) refuse("spring-damper '" + s.name + "' does not act through a corner's table");
    corners_[corner].springs.emplace_back(static_cast<int>(i), s.tableComponent);
  }
  for (size_t i = 0; i < m.bodies.size(); ++i)
    if (!known[i]) refuse("body '" + m.bodies[i].name + "' is not one the closed form carries");
}

void KinematicCar::updateSteering(double t) {
  if (t == steeringTime_) return;
  rackNow_ = rackInStep(t);
  steeringTime_ = t;
}

// The table at (travel, rack): R = rest Rz(psi) Rx(phi) Ry(theta), the
// carrier's angular velocity in its own axes E(phi, theta) a_dot, and the
// derivatives of both over the table's coordinates (as mb's tabulated joint).
template <typename T>
void KinematicCar::poseAt(int w, const T& travel, CornerPoseT<T>& P) const {
  const Corner& C = corners_[w];
  const double rack = C.steered ? rackNow_.value : 0.0;
  mb::SplineGrid::SampleT<T>& s = P.s;
  C.table->eval(travel, rack, rows_[w], s);
  const auto p = pm::sincos(s.f[3]), f = pm::sincos(s.f[4]), th = pm::sincos(s.f[5]);
  Mat3T<T> M;  // Rz(psi) Rx(phi) Ry(theta)
  M << p.c * th.c - p.s * f.s * th.s, -p.s * f.c, p.c * th.s + p.s * f.s * th.c,  //
      p.s * th.c + p.c * f.s * th.s, p.c * f.c, p.s * th.s - p.c * f.s * th.c,    //
      -f.c * th.s, f.s, f.c * th.c;
  P.R.noalias() = C.rest * M;
  P.t = Vec3T<T>(s.f[0], s.f[1], s.f[2]);
  P.E << -th.s * f.c, th.c, T(0.0), f.s, T(0.0), T(1.0), th.c * f.c, th.s, T(0.0);
  const Vec3T<T> da0(s.grad[3][0], s.grad[4][0], s.grad[5][0]);
  P.w0 = P.E * da0;
  P.ts = Vec3T<T>(s.grad[0][0], s.grad[1][0], s.grad[2][0]);
  P.phiS = f.s;
  P.phiC = f.c;
  P.thetaS = th.s;
  P.thetaC = th.c;
}

const KinematicCar::CornerPose& KinematicCar::cornerPose(int w, double travel) const {
  const double rack = corners_[w].steered ? rackNow_.value : 0.0;
  CornerPose& P = poses_[w];
  const auto travelBits = std::bit_cast<std::uint64_t>(travel), rackBits = std::bit_cast<std::uint64_t>(rack);
  if (P.valid && P.travelBits == travelBits && P.rackBits == rackBits) return P;
  poseAt(w, travel, P);
  P.travelBits = travelBits;
  P.rackBits = rackBits;
  P.valid = true;
  return P;
}

template <typename T>
void KinematicCar::cornerMotion(int w, const T& travel, const T& travelRate, CornerMotionT<T>& out,
                                bool withRates) const {
  if constexpr (!std::is_same_v<T, ad::Dual>) {
    cornerMotionOn(w, travel, travelRate, out, withRates);
  } else {
    // A corner's motion reads two of the state's directions, its travel and
    // travel rate: on those two, lifted onto the pass's (the same
    // derivatives as on the wide Dual, a fraction of the work).
    using D2 = ad::DualN<2>;
    CornerMotionT<D2> narrow;
    cornerMotionOn(w, ad::seeded<2>(travel.val, 0), ad::seeded<2>(travelRate.val, 1), narrow, withRates);
    const std::array<const ad::Dual*, 2> x{&travel, &travelRate};
    auto up = [&](const auto& from, auto& to) {
      for (Eigen::Index i = 0; i < from.size(); ++i) to.data()[i] = ad::lift(from.data()[i], x);
    };
    up(narrow.R, out.R);
    up(narrow.t, out.t);
    up(narrow.ts, out.ts);
    up(narrow.ws, out.ws);
    if (!withRates) return;
    up(narrow.velocity, out.velocity);
    up(narrow.omega, out.omega);
    up(narrow.accelBias, out.accelBias);
    up(narrow.alphaBias, out.alphaBias);
    out.springForce = ad::lift(narrow.springForce, x);
  }
}

template <typename T>
void KinematicCar::cornerMotionOn(int w, const T& travel, const T& travelRate, CornerMotionT<T>& out,
                                  bool withRates) const {
  using V3 = Vec3T<T>;
  const Corner& C = corners_[w];
  CornerPoseT<T> local;
  const CornerPoseT<T>* pose = &local;
  if constexpr (std::is_same_v<T, double>)
    pose = &cornerPose(w, travel);
  else
    poseAt(w, travel, local);
  const CornerPoseT<T>& P = *pose;
  const mb::SplineGrid::SampleT<T>& s = P.s;
  out.R = P.R;
  out.t = P.t;
  out.ts = P.ts;
  const V3& w0 = P.w0;
  out.ws.noalias() = out.R * w0;
  if (!withRates) return;
  const Mat3T<T>& E = P.E;
  const T rates[2] = {travelRate, T(C.steered ? rackNow_.rate : 0.0)};
  // dE/dphi has one non-zero column (the first), dE/dtheta two (the first two).
  const T &fs = P.phiS, &fc = P.phiC, &ts = P.thetaS, &tc = P.thetaC;
  const V3 Ephi0(ts * fs, fc, -tc * fs), Etheta0(-tc * fc, T(0.0), -ts * fc), Etheta1(-ts, T(0.0), tc);
  // The angles' rates adot = sum_k r_k da/ds_k, and the table's second
  // derivatives along the rates, sum_kl r_k r_l d2/ds_k ds_l: the
  // accelerations' bias terms are bilinear in the rates, so both sums are
  // taken once (dE/dt adot = Ephi0 phidot psidot + Etheta0 thetadot psidot +
  // Etheta1 thetadot phidot).
  V3 adot = V3(s.grad[3][0], s.grad[4][0], s.grad[5][0]) * rates[0];
  const T r00 = rates[0] * rates[0];
  std::array<T, 6> along2;
  for (int c = 0; c < 6; ++c) along2[c] = s.hess[c][0] * r00;
  V3 wb = w0 * rates[0], wdot = V3::Zero();
  out.velocity = out.ts * rates[0];
  out.accelBias.setZero();
  if (C.steered) {
    const V3 da1(s.grad[3][1], s.grad[4][1], s.grad[5][1]);
    adot += da1 * rates[1];
    const V3 w1 = E * da1;
    wb += w1 * rates[1];
    wdot += w1 * rackNow_.accel;
    const V3 t1(s.grad[0][1], s.grad[1][1], s.grad[2][1]);
    out.velocity += t1 * rates[1];
    out.accelBias += t1 * rackNow_.accel;
    const T r01 = 2.0 * rates[0] * rates[1], r11 = rates[1] * rates[1];
    for (int c = 0; c < 6; ++c) along2[c] += s.hess[c][1] * r01 + s.hess[c][2] * r11;
  }
  wdot += Ephi0 * (adot.y() * adot.x()) + Etheta0 * (adot.z() * adot.x()) + Etheta1 * (adot.z() * adot.y()) +
          E * V3(along2[3], along2[4], along2[5]);
  out.accelBias += V3(along2[0], along2[1], along2[2]);
  out.omega.noalias() = out.R * wb;
  out.alphaBias.noalias() = out.R * wdot;
  // The springs and dampers of the corner through the table's lengths: the
  // generalised force F dL/d(travel) (their reaction on the rack is the rack's).
  out.springForce = T(0.0);
  for (const auto& [k, c] : C.springs) {
    const T L = s.f[c], Ls = s.grad[c][0];
    const T Ldot = Ls * rates[0] + (C.steered ? T(s.grad[c][1] * rates[1]) : T(0.0));
    out.springForce += vehicle_.model.springs[k].force(L, Ldot) * Ls;
  }
}

void KinematicCar::beginStep(double t, const integ::Vec& q, const integ::Vec&) {
  steeringTime_ = std::numeric_limits<double>::quiet_NaN();  // the rack's segment may have changed at a tick
  if (!forces_.needsBeginStep(t)) return;
  updateSteering(t);
  const Mat3 R0 = mb::quatToMatrix(q.data() + 3);
  const Vec3 p = q.head<3>();
  std::array<Vec3, 4> centres, axes;
  for (int w = 0; w < 4; ++w) {
    CornerMotion cm;
    cornerMotion(w, q(TravelQ + w), 0.0, cm, false);
    centres[w] = p + R0 * (cm.t + cm.R * corners_[w].centre);
    axes[w] = R0 * (cm.R * corners_[w].axisY);
  }
  forces_.beginContacts(t, centres, axes);
}

integ::EvalStatus KinematicCar::acceptStep(double t, double h, const integ::Vec& q, const integ::Vec& v,
                                           integ::Message& msg) {
  const integ::EvalStatus status = acceptWheels(t, h, q, v, msg);
  steeringTime_ = std::numeric_limits<double>::quiet_NaN();
  return status;
}

// The equations of motion by virtual power (Kane's form), in chassis axes:
// F = sum over bodies of (partial velocity) . (inertial force - applied
// force). Each corner's forces are reduced to a wrench about its carrier's
// origin, whose partial velocities are the chassis' motion, its travel's
// (ts, ws) and, for the wheel alone, the spin about its axis.
// Written for T double (the residual: it also keeps the chassis' pose, the
// corners' motion, the wheels' kinematics and the tyres' outputs for the
// step's acceptance, the fast columns and telemetry) and T ad::Dual (the
// Jacobian: nothing kept).
template <typename T>
void KinematicCar::equations(double t, const T* q, const T* v, const integ::Vec& a, T* F) {
  constexpr bool kKeep = std::is_same_v<T, double>;
  using V3 = Vec3T<T>;
  using M3 = Mat3T<T>;
  updateSteering(t);
  const double h = forces_.sinceAccepted(t);
  const VehicleSpec& spec = vehicle_.spec;
  const M3 R0 = Eigen::Quaternion<T>(q[3], q[4], q[5], q[6]).toRotationMatrix();
  const V3 p(q[0], q[1], q[2]);
  if constexpr (kKeep) {
    chassisAxes_ = R0;
    chassisOrigin_ = p;
  }
  const V3 V(v[0], v[1], v[2]), om(v[3], v[4], v[5]);
  const Vec3 alpha = a.segment<3>(3);
  const V3 g = R0.transpose() * gravity_;
  const V3 A0 = a.segment<3>(0) + om.cross(V);  // the chassis origin's acceleration
  auto pointAccel = [&](const V3& x) -> V3 { return A0 + alpha.cross(x) + om.cross(V3(om.cross(x))); };

  // The chassis and what rides on it without a coordinate of its own: net
  // (inertial less applied) force and moment about the chassis origin.
  V3 FV = chassisMass_ * (pointAccel(chassisCom_.cast<T>()) - g);
  V3 FW = chassisCom_.cross(FV) + chassisInertia_ * alpha + om.cross(V3(chassisInertia_ * om));
  if (rackMass_ > 0) {
    const Vec3 x = rackCom0_ + rackNow_.value * rackAxis_;
    const V3 Fr = rackMass_ * (pointAccel(x.cast<T>()) + 2 * rackNow_.rate * om.cross(rackAxis_) +
                               rackNow_.accel * rackAxis_ - g);
    FV += Fr;
    FW += x.cross(Fr) + rackInertia_ * alpha + om.cross(V3(rackInertia_ * om));
  }
  // Air: drag at the chassis' centre of mass, lift above the axles.
  const V3 vc = V + om.cross(chassisCom_);
  if (spec.dragArea > 0) {
    const V3 drag = -spec.dragArea * ad::norm0(vc) * vc;
    FV -= drag;
    FW -= chassisCom_.cross(drag);
  }
  if (spec.liftAreaFront != 0 || spec.liftAreaRear != 0) {
    for (int axle = 0; axle < 2; ++axle) {
      const Vec3 centre = 0.5 * (vehicle_.layout.wheelCentreAtDesign[2 * axle] + vehicle_.layout.wheelCentreAtDesign[2 * axle + 1]);
      const double area = axle == 0 ? spec.liftAreaFront : spec.liftAreaRear;
      const T up = area * vc.x() * vc.x();
      const V3 lift = up * V3(Vec3::UnitZ());
      FV -= lift;
      FW -= Vec3(centre.x(), chassisCom_.y(), chassisCom_.z()).cross(lift);
    }
  }

  std::array<CornerMotionT<T>, 4> dualMotions;
  std::array<CornerMotionT<T>, 4>* motions = &dualMotions;
  if constexpr (kKeep) motions = &motions_;  // kept: fastColumnParts takes the tyres as this residual does
  std::array<CornerMotionT<T>, 4>& cm = *motions;
  for (int w = 0; w < 4; ++w) cornerMotion(w, q[TravelQ + w], v[TravelV + w], cm[w], true);
  // The wheel centres relative to their carriers' origins, chassis axes
  // (the bars, the tyres and the spins read them).
  std::array<V3, 4> centreArm;
  for (int w = 0; w < 4; ++w) centreArm[w].noalias() = cm[w].R * corners_[w].centre;
  // Anti-roll bars between the wheel centres and the chassis, on the
  // travels: a pair of forces at the same point, working on the travel alone.
  std::array<T, 4> Qtravel{T(0.0), T(0.0), T(0.0), T(0.0)};
  for (const AntiRollBarSpec& bar : spec.antiRollBars) {
    auto centreZ = [&](int w) -> T {
      return (cm[w].t.z() + centreArm[w].z()) - vehicle_.layout.wheelCentreAtDesign[w].z();
    };
    const T f = bar.rate * (centreZ(bar.left) - centreZ(bar.right));
    for (const auto& [w, sign] : {std::pair{bar.left, 1.0}, std::pair{bar.right, -1.0}}) {
      // d/d(travel) of the centre's height: ts + ws x arm, its z.
      const V3& ws = cm[w].ws;
      const T centreRateZ = cm[w].ts.z() + (ws.x() * centreArm[w].y() - ws.y() * centreArm[w].x());
      Qtravel[w] -= sign * f * centreRateZ;
    }
  }

  // The corners: inertial less applied wrench about the carrier's origin.
  std::array<V3, 4> Fc, Mc, spinAxis, alphaC;
  std::array<T, 4> Qspin{T(0.0), T(0.0), T(0.0), T(0.0)}, relativeSpin;
  for (int w = 0; w < 4; ++w) {
    const Corner& C = corners_[w];
    const CornerMotionT<T>& m = cm[w];
    const double sdd = a(TravelV + w), spinAcc = a(SpinV + w);
    const T spin = v[SpinV + w];
    const V3 omegaC = om + m.omega;
    alphaC[w] = alpha + om.cross(m.omega) + m.alphaBias + sdd * m.ws;
    const V3 accO = pointAccel(m.t) + 2 * om.cross(m.velocity) + m.accelBias + sdd * m.ts;
    const V3 arm = m.R * C.com;
    const V3 accCom = accO + alphaC[w].cross(arm) + omegaC.cross(V3(omegaC.cross(arm)));
    const V3 yAxis = m.R * C.axisY;
    spinAxis[w] = C.spinSign * yAxis;
    Fc[w] = C.mass * (accCom - g);
    // Euler's equation in the carrier's axes (its inertia constant there).
    const V3 wb = m.R.transpose() * omegaC, ab = m.R.transpose() * alphaC[w];
    const V3 Iw = C.inertia * wb;
    Mc[w] = arm.cross(Fc[w]) + m.R * V3(C.inertia * ab + wb.cross(Iw)) +
            C.spinInertia * (spinAcc * spinAxis[w] + spin * omegaC.cross(spinAxis[w]));

    // The tyre on its contact plane, the brake.
    const V3 centre = m.t + centreArm[w];
    tyre::WheelKinematicsT<T> k;
    k.centre = p + R0 * centre;
    k.spinAxis = R0 * yAxis;
    k.centreVelocity = R0 * V3(V + om.cross(centre) + m.velocity + m.omega.cross(centreArm[w]));
    k.spinRate = yAxis.dot(omegaC) + C.spinSign * spin;
    relativeSpin[w] = C.spinSign * spin;
    tyre::TyreOutputT<T> dual;
    const tyre::TyreOutputT<T>& tyre = wheelTyre(w, k, relativeSpin[w], h, std::optional<T>(), dual);
    if (tyre.inContact) {
      const V3 Ft = R0.transpose() * tyre.force, M = R0.transpose() * tyre.moment;
      const V3 at = R0.transpose() * V3(tyre.point - p);
      Fc[w] -= Ft;
      Mc[w] -= V3(at - m.t).cross(Ft) + M;
      Qspin[w] += spinAxis[w].dot(V3(V3(at - centre).cross(Ft) + M));
    }
    Qspin[w] += C.spinSign * forces_.brakeTorque(w, relativeSpin[w], h);
  }
  // Drive torques: a powertrain's from its driveline at the crank's and the
  // wheels' speeds now (the crank's own torque: the engine's less the
  // clutch's), or as the driver holds them.
  const bool engine = engineMultibodyV_ >= 0;
  const DriveTorques<T> drive = driveTorques(engine ? v[EngineV] : T(0.0), relativeSpin, h);
  for (int w = 0; w < 4; ++w) {
    if (ad::value(drive.wheel[w]) == 0.0) continue;
    Qspin[w] += corners_[w].spinSign * drive.wheel[w];
    if (spec.driveReaction == DriveReaction::Carrier) continue;
    const V3 torque = drive.wheel[w] * corners_[w].spinSign * spinAxis[w];  // about the wheel's y
    Mc[w] -= torque;
    if (spec.driveReaction == DriveReaction::Chassis) FW += torque;
  }
  if (engine) {
    // The crank's rotor: d/dt of its angular momentum about the chassis' x.
    const Vec3 ax = Vec3::UnitX();
    const T spin = om.x() + v[EngineV];
    const double spinRate = alpha.x() + a(EngineV);
    FW += engineInertia_ * (spinRate * ax + spin * om.cross(ax));
    F[EngineV] = engineInertia_ * spinRate - drive.crank;
  }
  // Projection on the partial velocities.
  for (int w = 0; w < 4; ++w) {
    const CornerMotionT<T>& m = cm[w];
    FV += Fc[w];
    FW += Mc[w] + m.t.cross(Fc[w]);
    F[TravelV + w] = m.ts.dot(Fc[w]) + m.ws.dot(Mc[w]) - m.springForce - Qtravel[w];
    F[SpinV + w] = corners_[w].spinInertia * (a(SpinV + w) + spinAxis[w].dot(alphaC[w])) - Qspin[w];
  }
  for (int i = 0; i < 3; ++i) {
    F[i] = FV(i);
    F[3 + i] = FW(i);
  }
}

template void KinematicCar::equations(double, const double*, const double*, const integ::Vec&, double*);
template void KinematicCar::equations(double, const ad::Dual*, const ad::Dual*, const integ::Vec&, ad::Dual*);

// sum over bodies of m Jv^T Jv + Jw^T I Jw with the residual's partial
// velocities; the rotors' (spins, crank) about their axes.
bool KinematicCar::massMatrix(double t, const integ::Vec& q, integ::Mat& Fa) {
  updateSteering(t);
  Fa.setZero(n_, n_);
  Eigen::Matrix<double, 3, Eigen::Dynamic> Jv(3, n_), Jw(3, n_);
  // A body riding on the chassis with its centre of mass at com (chassis axes).
  auto onChassis = [&](const Vec3& com) {
    Jv.setZero();
    Jw.setZero();
    Jv.leftCols<3>().setIdentity();
    Jv.middleCols<3>(3) << 0, com.z(), -com.y(), -com.z(), 0, com.x(), com.y(), -com.x(), 0;  // -[com]x
    Jw.middleCols<3>(3).setIdentity();
  };
  auto add = [&](double mass, const Mat3& I) { Fa.noalias() += mass * Jv.transpose() * Jv + Jw.transpose() * I * Jw; };
  onChassis(chassisCom_);
  add(chassisMass_, chassisInertia_);
  if (rackMass_ > 0) {
    onChassis(rackCom0_ + rackNow_.value * rackAxis_);
    add(rackMass_, rackInertia_);
  }
  for (int w = 0; w < 4; ++w) {
    const Corner& C = corners_[w];
    CornerMotion m;
    cornerMotion(w, q(TravelQ + w), 0.0, m, false);
    const Vec3 arm = m.R * C.com;
    onChassis(m.t + arm);
    Jv.col(TravelV + w) = m.ts + m.ws.cross(arm);
    Jw.col(TravelV + w) = m.ws;
    add(C.mass, m.R * C.inertia * m.R.transpose());
    // The spin: its rotor's momentum along the axis couples it to the corner's rotation.
    const Vec3 axis = C.spinSign * (m.R * C.axisY);
    const Eigen::RowVectorXd coupling = C.spinInertia * axis.transpose() * Jw;
    Fa.row(SpinV + w) += coupling;
    Fa.col(SpinV + w) += coupling.transpose();
    Fa(SpinV + w, SpinV + w) += C.spinInertia;
  }
  if (engineMultibodyV_ >= 0) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n_);
    u(3) = 1.0;  // the chassis' rate about x
    u(EngineV) = 1.0;
    Fa.noalias() += engineInertia_ * u * u.transpose();
  }
  return true;
}

void KinematicCar::toMultibody(double t, const integ::Vec& q, const integ::Vec& v, integ::Vec& qm, integ::Vec& vm) const {
  const mb::Model& m = vehicle_.model;
  qm = mb::neutralPositions(m);
  vm.setZero(m.nv);
  qm.head<7>() = q.head<7>();  // the chassis' free joint (body 0)
  vm.head<6>() = v.head<6>();
  for (int w = 0; w < 4; ++w) {
    const Corner& C = corners_[w];
    qm(C.travelQ) = q(TravelQ + w);
    vm(C.travelV) = v(TravelV + w);
    qm(C.spinQ) = q(SpinQ + w);
    vm(C.spinV) = v(SpinV + w);
  }
  if (engineMultibodyV_ >= 0) {
    qm(engineMultibodyQ_) = q(EngineQ);
    vm(engineMultibodyV_) = v(EngineV);
  }
  driveMultibody(t, qm, vm);
}

void KinematicCar::fromMultibody(const integ::Vec& qm, const integ::Vec& vm, integ::Vec& q, integ::Vec& v) const {
  q.resize(nq_);
  v.resize(n_);
  q.head<7>() = qm.head<7>();
  v.head<6>() = vm.head<6>();
  for (int w = 0; w < 4; ++w) {
    const Corner& C = corners_[w];
    q(TravelQ + w) = qm(C.travelQ);
    v(TravelV + w) = vm(C.travelV);
    q(SpinQ + w) = qm(C.spinQ);
    v(SpinV + w) = vm(C.spinV);
  }
  if (engineMultibodyV_ >= 0) {
    q(EngineQ) = qm(engineMultibodyQ_);
    v(EngineV) = vm(engineMultibodyV_);
  }
}

// As the residual takes them: the tyre's force and moment on the carrier
// (about its origin), the carrier's on the travel and the chassis, the
// moment about the spin axis on the spin.
void KinematicCar::addTyreForces(int w, const tyre::TyreOutput& tyre, double scale, Eigen::Ref<integ::Vec> col) const {
  if (!tyre.inContact) return;
  const CornerMotion& c = motions_[w];
  const Corner& C = corners_[w];
  const Vec3 centre = c.t + c.R * C.centre, spinAxis = C.spinSign * (c.R * C.axisY);
  const Vec3 F = scale * (chassisAxes_.transpose() * tyre.force), M = scale * (chassisAxes_.transpose() * tyre.moment);
  const Vec3 at = chassisAxes_.transpose() * (tyre.point - chassisOrigin_);
  const Vec3 onCarrier = (at - c.t).cross(F) + M;
  col.segment<3>(0) -= F;
  col.segment<3>(3) -= onCarrier + c.t.cross(F);
  col(TravelV + w) -= c.ts.dot(F) + c.ws.dot(onCarrier);
  col(SpinV + w) -= spinAxis.dot((at - centre).cross(F) + M);
}

void KinematicCar::addDriveTorque(int w, double scale, Eigen::Ref<integ::Vec> col) const {
  const double sign = corners_[w].spinSign;
  col(SpinV + w) -= scale * sign;
  const DriveReaction reaction = vehicle_.spec.driveReaction;
  if (reaction == DriveReaction::Carrier) return;
  const CornerMotion& m = motions_[w];
  const Vec3 torque = scale * (m.R * corners_[w].axisY);  // on the wheel about its y, the carrier takes it back
  col(TravelV + w) -= m.ws.dot(torque);
  if (reaction == DriveReaction::None) col.segment<3>(3) -= torque;  // Chassis: the chassis takes it back too
}

}  // namespace bdfcar::vehicle
