#include "vehicle/kinematic_car.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "multibody/joint.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
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
const KinematicCar::CornerPose& KinematicCar::cornerPose(int w, double travel) const {
  const Corner& C = corners_[w];
  const double rack = C.steered ? rackNow_.value : 0.0;
  CornerPose& P = poses_[w];
  const auto travelBits = std::bit_cast<std::uint64_t>(travel), rackBits = std::bit_cast<std::uint64_t>(rack);
  if (P.valid && P.travelBits == travelBits && P.rackBits == rackBits) return P;
  mb::SplineGrid::Sample& s = P.s;
  C.table->eval(travel, rack, rows_[w], s);
  const pm::SinCos p = pm::sincos(s.f[3]), f = pm::sincos(s.f[4]), th = pm::sincos(s.f[5]);
  Mat3 M;  // Rz(psi) Rx(phi) Ry(theta)
  M << p.c * th.c - p.s * f.s * th.s, -p.s * f.c, p.c * th.s + p.s * f.s * th.c,  //
      p.s * th.c + p.c * f.s * th.s, p.c * f.c, p.s * th.s - p.c * f.s * th.c,    //
      -f.c * th.s, f.s, f.c * th.c;
  P.R.noalias() = C.rest * M;
  P.t = Vec3(s.f[0], s.f[1], s.f[2]);
  P.E << -th.s * f.c, th.c, 0, f.s, 0, 1, th.c * f.c, th.s, 0;
  const Vec3 da0(s.grad[3][0], s.grad[4][0], s.grad[5][0]);
  P.w0 = P.E * da0;
  P.ts = Vec3(s.grad[0][0], s.grad[1][0], s.grad[2][0]);
  P.phi = f;
  P.theta = th;
  P.travelBits = travelBits;
  P.rackBits = rackBits;
  P.valid = true;
  return P;
}

void KinematicCar::cornerMotion(int w, double travel, double travelRate, CornerMotion& out, bool withRates) const {
  const Corner& C = corners_[w];
  const CornerPose& P = cornerPose(w, travel);
  const mb::SplineGrid::Sample& s = P.s;
  const pm::SinCos &f = P.phi, &th = P.theta;
  out.R = P.R;
  out.t = P.t;
  out.ts = P.ts;
  const Vec3& w0 = P.w0;
  out.ws.noalias() = out.R * w0;
  if (!withRates) return;
  const Mat3& E = P.E;
  const int nv = C.steered ? 2 : 1;
  const double rates[2] = {travelRate, C.steered ? rackNow_.rate : 0.0};
  // dE/dphi has one non-zero column (the first), dE/dtheta two (the first two).
  const Vec3 Ephi0(th.s * f.s, f.c, -th.c * f.s), Etheta0(-th.c * f.c, 0, -th.s * f.c), Etheta1(-th.s, 0, th.c);
  Vec3 wb = w0 * rates[0], wdot = Vec3::Zero();
  out.velocity = out.ts * rates[0];
  out.accelBias.setZero();
  if (C.steered) {
    const Vec3 da1(s.grad[3][1], s.grad[4][1], s.grad[5][1]);
    const Vec3 w1 = E * da1;
    wb += w1 * rates[1];
    wdot += w1 * rackNow_.accel;
    const Vec3 t1(s.grad[0][1], s.grad[1][1], s.grad[2][1]);
    out.velocity += t1 * rates[1];
    out.accelBias += t1 * rackNow_.accel;
  }
  for (int k = 0; k < nv; ++k) {
    const Vec3 da(s.grad[3][k], s.grad[4][k], s.grad[5][k]);
    for (int l = 0; l < nv; ++l) {
      const int h = k + l;  // (0,0) -> xx, (0,1) -> xy, (1,1) -> yy
      const double rr = rates[k] * rates[l];
      const Vec3 d2a(s.hess[3][h], s.hess[4][h], s.hess[5][h]);
      wdot += (Ephi0 * (s.grad[4][l] * da.x()) + Etheta0 * (s.grad[5][l] * da.x()) + Etheta1 * (s.grad[5][l] * da.y()) +
               E * d2a) * rr;
      out.accelBias += Vec3(s.hess[0][h], s.hess[1][h], s.hess[2][h]) * rr;
    }
  }
  out.omega.noalias() = out.R * wb;
  out.alphaBias.noalias() = out.R * wdot;
  // The springs and dampers of the corner through the table's lengths: the
  // generalised force F dL/d(travel) (their reaction on the rack is the rack's).
  out.springForce = 0;
  for (const auto& [k, c] : C.springs) {
    const double L = s.f[c], Ls = s.grad[c][0];
    const double Ldot = Ls * rates[0] + (C.steered ? s.grad[c][1] * rates[1] : 0.0);
    out.springForce += vehicle_.model.springs[k].force(L, Ldot) * Ls;
  }
}

void KinematicCar::beginStep(double t, const integ::Vec& q, const integ::Vec&) {
  steeringTime_ = std::numeric_limits<double>::quiet_NaN();  // the rack's segment may have changed at a tick
  if (!forces_.needsBeginStep()) return;
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
  forces_.beginContacts(centres, axes);
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
integ::EvalStatus KinematicCar::residual(double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& a,
                                         const integ::Vec&, integ::Residual& out, bool, integ::Message& msg) {
  updateSteering(t);
  const double h = forces_.sinceAccepted(t);
  const VehicleSpec& spec = vehicle_.spec;
  const Mat3 R0 = mb::quatToMatrix(q.data() + 3);
  const Vec3 p = q.head<3>();
  chassisAxes_ = R0;
  chassisOrigin_ = p;
  const Vec3 V = v.segment<3>(0), om = v.segment<3>(3), alpha = a.segment<3>(3);
  const Vec3 g = R0.transpose() * gravity_;
  const Vec3 A0 = a.segment<3>(0) + om.cross(V);  // the chassis origin's acceleration
  auto pointAccel = [&](const Vec3& x) -> Vec3 { return A0 + alpha.cross(x) + om.cross(om.cross(x)); };

  // The chassis and what rides on it without a coordinate of its own: net
  // (inertial less applied) force and moment about the chassis origin.
  Vec3 FV = chassisMass_ * (pointAccel(chassisCom_) - g);
  Vec3 FW = chassisCom_.cross(FV) + chassisInertia_ * alpha + om.cross(chassisInertia_ * om);
  if (rackMass_ > 0) {
    const Vec3 x = rackCom0_ + rackNow_.value * rackAxis_;
    const Vec3 F = rackMass_ * (pointAccel(x) + 2 * rackNow_.rate * om.cross(rackAxis_) + rackNow_.accel * rackAxis_ - g);
    FV += F;
    FW += x.cross(F) + rackInertia_ * alpha + om.cross(rackInertia_ * om);
  }
  // Air: drag at the chassis' centre of mass, lift above the axles.
  const Vec3 vc = V + om.cross(chassisCom_);
  if (spec.dragArea > 0) {
    const Vec3 drag = -spec.dragArea * vc.norm() * vc;
    FV -= drag;
    FW -= chassisCom_.cross(drag);
  }
  if (spec.liftAreaFront != 0 || spec.liftAreaRear != 0) {
    for (int axle = 0; axle < 2; ++axle) {
      const Vec3 centre = 0.5 * (vehicle_.layout.wheelCentreAtDesign[2 * axle] + vehicle_.layout.wheelCentreAtDesign[2 * axle + 1]);
      const double area = axle == 0 ? spec.liftAreaFront : spec.liftAreaRear;
      const Vec3 lift = area * vc.x() * vc.x() * Vec3::UnitZ();
      FV -= lift;
      FW -= Vec3(centre.x(), chassisCom_.y(), chassisCom_.z()).cross(lift);
    }
  }

  std::array<CornerMotion, 4>& cm = motions_;  // kept: fastColumnParts takes the tyres as this residual does
  for (int w = 0; w < 4; ++w) cornerMotion(w, q(TravelQ + w), v(TravelV + w), cm[w], true);
  // Anti-roll bars between the wheel centres and the chassis, on the
  // travels: a pair of forces at the same point, working on the travel alone.
  std::array<double, 4> Qtravel{};
  for (const AntiRollBarSpec& bar : spec.antiRollBars) {
    auto centreZ = [&](int w) { return (cm[w].t + cm[w].R * corners_[w].centre).z() - vehicle_.layout.wheelCentreAtDesign[w].z(); };
    const double f = bar.rate * (centreZ(bar.left) - centreZ(bar.right));
    for (const auto& [w, sign] : {std::pair{bar.left, 1.0}, std::pair{bar.right, -1.0}}) {
      const Vec3 centreRate = cm[w].ts + cm[w].ws.cross(cm[w].R * corners_[w].centre);
      Qtravel[w] -= sign * f * centreRate.z();
    }
  }

  // The corners: inertial less applied wrench about the carrier's origin.
  std::array<Vec3, 4> Fc, Mc, spinAxis, alphaC;
  std::array<double, 4> Qspin{};
  for (int w = 0; w < 4; ++w) {
    const Corner& C = corners_[w];
    const CornerMotion& m = cm[w];
    const double sdd = a(TravelV + w), spin = v(SpinV + w), spinAcc = a(SpinV + w);
    const Vec3 omegaC = om + m.omega;
    alphaC[w] = alpha + om.cross(m.omega) + m.alphaBias + sdd * m.ws;
    const Vec3 accO = pointAccel(m.t) + 2 * om.cross(m.velocity) + m.accelBias + sdd * m.ts;
    const Vec3 arm = m.R * C.com;
    const Vec3 accCom = accO + alphaC[w].cross(arm) + omegaC.cross(omegaC.cross(arm));
    const Vec3 yAxis = m.R * C.axisY;
    spinAxis[w] = C.spinSign * yAxis;
    Fc[w] = C.mass * (accCom - g);
    // Euler's equation in the carrier's axes (its inertia constant there).
    const Vec3 wb = m.R.transpose() * omegaC, ab = m.R.transpose() * alphaC[w];
    const Vec3 Iw = C.inertia * wb;
    Mc[w] = arm.cross(Fc[w]) + m.R * (C.inertia * ab + wb.cross(Iw)) +
            C.spinInertia * (spinAcc * spinAxis[w] + spin * omegaC.cross(spinAxis[w]));

    // The tyre on its contact plane, the brake.
    const Vec3 centre = m.t + m.R * C.centre;
    tyre::WheelKinematics& k = kinematics_[w];
    k.centre = p + R0 * centre;
    k.spinAxis = R0 * yAxis;
    k.centreVelocity = R0 * (V + om.cross(centre) + m.velocity + m.omega.cross(centre - m.t));
    k.spinRate = yAxis.dot(omegaC) + C.spinSign * spin;
    relativeSpin_[w] = C.spinSign * spin;
    const tyre::TyreOutput& tyre = forces_.evaluateTyre(w, k, h, std::nullopt);
    if (tyre.inContact) {
      const Vec3 F = R0.transpose() * tyre.force, M = R0.transpose() * tyre.moment;
      const Vec3 at = R0.transpose() * (tyre.point - p);
      Fc[w] -= F;
      Mc[w] -= (at - m.t).cross(F) + M;
      Qspin[w] += spinAxis[w].dot((at - centre).cross(F) + M);
    }
    Qspin[w] += C.spinSign * forces_.brakeTorque(w, relativeSpin_[w], h);
  }
  // Drive torques: a powertrain's from its driveline at the crank's and the
  // wheels' speeds now (the crank's own torque: the engine's less the
  // clutch's), or as the driver holds them.
  const bool engine = engineMultibodyV_ >= 0;
  engineSpeed_ = engine ? v(EngineV) : 0.0;
  const double crankTorque = engine ? forces_.drivelineTorques(engineSpeed_, relativeSpin_, h) : 0.0;
  for (int w = 0; w < 4; ++w) {
    const double drive = forces_.wheels()[w].driveTorque;
    if (drive == 0.0) continue;
    Qspin[w] += corners_[w].spinSign * drive;
    if (spec.driveReaction == DriveReaction::Carrier) continue;
    const Vec3 torque = drive * corners_[w].spinSign * spinAxis[w];  // about the wheel's y
    Mc[w] -= torque;
    if (spec.driveReaction == DriveReaction::Chassis) FW += torque;
  }
  if (engine) {
    // The crank's rotor: d/dt of its angular momentum about the chassis' x.
    const Vec3 ax = Vec3::UnitX();
    const double spin = om.x() + v(EngineV), spinRate = alpha.x() + a(EngineV);
    FW += engineInertia_ * (spinRate * ax + spin * om.cross(ax));
    out.F(EngineV) = engineInertia_ * spinRate - crankTorque;
  }
  // Projection on the partial velocities.
  for (int w = 0; w < 4; ++w) {
    const CornerMotion& m = cm[w];
    FV += Fc[w];
    FW += Mc[w] + m.t.cross(Fc[w]);
    out.F(TravelV + w) = m.ts.dot(Fc[w]) + m.ws.dot(Mc[w]) - m.springForce - Qtravel[w];
    out.F(SpinV + w) = corners_[w].spinInertia * (a(SpinV + w) + spinAxis[w].dot(alphaC[w])) - Qspin[w];
  }
  out.F.segment<3>(0) = FV;
  out.F.segment<3>(3) = FW;
  if (!out.F.allFinite()) {
    msg.set("non-finite equations of motion at t = %.6g s", t);
    return integ::EvalStatus::Recoverable;
  }
  return integ::EvalStatus::Ok;
}

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
