#include "vehicle/planar_car.h"

#include <cmath>
#include <limits>
#include <string>

#include "multibody/joint.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "autodiff.h"
#include "portable_math.h"
#include "terrain/terrain_data.h"

namespace bdfcar::vehicle {

namespace {

const Vec3 kX = Vec3::UnitX(), kY = Vec3::UnitY(), kZ = Vec3::UnitZ();

[[noreturn]] void refuse(const std::string& what) { throw mb::ModelError("closed-form planar car: " + what); }

// The base frame's yaw: base -> world (toWorld) and back (toLocal).
template <typename T>
struct Heading {
  T c, s;
  Vec3T<T> toWorld(const Vec3T<T>& v) const { return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()}; }
  Vec3T<T> toLocal(const Vec3T<T>& v) const { return {c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z()}; }
};
template <typename T>
Heading<T> headingOf(const T& angle) {
  const auto r = pm::sincos(angle);
  return {r.c, r.s};
}

// Rx(roll) Ry(pitch): the universal joint's rotation.
template <typename T>
Mat3T<T> rollPitch(const T& roll, const T& pitch) {
  const auto f = pm::sincos(roll), t = pm::sincos(pitch);
  Mat3T<T> R;
  R << t.c, T(0.0), t.s,         //
      f.s * t.s, f.c, -f.s * t.c,  //
      -f.c * t.s, f.s, f.c * t.c;
  return R;
}

}  // namespace

PlanarCar::PlanarCar(const Vehicle& planar, const terrain::Terrain& terrain, const TerrainContactOptions& options)
    : ClosedFormCar(planar, terrain, options), steeringTime_(std::numeric_limits<double>::quiet_NaN()) {
  if (!planar.planar) refuse("the vehicle is not a planar model");
  n_ = nq_ = kCoordinates;
  chassisJoint_ = mb::JointType::Planar;  // the base's
  chassisQ_ = chassisV_ = 3;
  fastColumns_ = {Spin, Spin + 1, Spin + 2, Spin + 3};
  const mb::Model& m = planar.model;
  const VehicleLayout& L = planar.layout;
  const mb::Body& base = m.bodies[L.base];
  const mb::Body& sprung = m.bodies[L.chassis];
  if (base.joint != mb::JointType::Planar || base.parent != mb::kGround || !base.inChild.origin.isZero() ||
      !base.inChild.axes.isIdentity() || !base.inParent.axes.isIdentity())
    refuse("the base is not on a level planar joint");
  if (sprung.joint != mb::JointType::Universal || sprung.parent != L.base || !sprung.inParent.axes.isIdentity())
    refuse("the sprung body does not roll and pitch on the base");
  groundZ_ = base.inParent.origin.z();
  gravity_ = m.gravity;

  // The sprung body about its joint: x_base = A + Rx Ry rest (x_body - o).
  axisPoint_ = sprung.inParent.origin;
  sprungRest_ = sprung.inChild.axes.transpose();
  jointInBody_ = sprung.inChild.origin;
  sprungMass_ = sprung.mass;
  comArm0_ = sprungRest_ * (sprung.com - jointInBody_);
  inertia0_ = sprungRest_ * fullInertia(sprung) * sprungRest_.transpose();
  crankAxis0_ = sprungRest_.col(0);
  for (int w = 0; w < 4; ++w) {
    cornerArm_[w] = sprungRest_ * (planar.planar->sprungPoint[w] - jointInBody_);
    turnPerTravel_[w] = sprungRest_ * planar.planar->turnPerTravel[w];
  }

  // Everything else rides on the base: the bodies fixed in it lumped into
  // one, those the rack moves (the rack, the steered carriers and wheels)
  // tabulated over the rack travel (below).
  mb::Data d = mb::makeData(m);
  const Eigen::VectorXd q0 = designPositions(planar);
  mb::updatePositions(m, q0, d);
  const Vec3 origin = d.p[L.base];
  std::vector<int> steered;  // the bodies the rack moves
  for (const mb::CutJoint& c : m.cutJoints)
    if (c.type != mb::CutJointType::Driver) refuse("cut joint '" + c.name + "' is not a rack driver");
  if (L.engine >= 0) {
    // The crank: a massless rotor about the sprung body's x axis (addEngine).
    const mb::Body& e = m.bodies[L.engine];
    if (e.parent != L.chassis || e.mass != 0 || !e.inertia.isZero() || !e.rotorAxis.isApprox(Vec3::UnitX()) ||
        !e.inParent.axes.col(2).isApprox(Vec3::UnitX()) || !e.inChild.axes.col(2).isApprox(Vec3::UnitX()))
      refuse("the engine is not a rotor about the sprung body's x axis");
    engineInertia_ = e.rotorInertia;
    engineQ_ = e.qIndex;
    engineV_ = e.vIndex;
    n_ = nq_ = kCoordinates + 1;
  }
  if (m.nv != n_ + static_cast<int>(drivenCoordinates_.size()) || m.nq != m.nv)
    refuse("the planar model has coordinates the closed form does not carry");
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const mb::Body& b = m.bodies[i];
    if (static_cast<int>(i) == L.chassis || static_cast<int>(i) == L.engine) continue;
    if (b.parent == L.chassis) refuse("body '" + b.name + "' rides on the sprung body");
    // Moved by the rack: its joint, or one below it, has a driven coordinate.
    bool moves = false;
    for (int k = static_cast<int>(i); k >= 0; k = m.bodies[k].parent)
      for (const auto& driven : drivenCoordinates_)
        moves = moves || (driven.second >= m.bodies[k].vIndex && driven.second < m.bodies[k].vIndex + m.bodies[k].nv);
    if (moves) {
      steered.push_back(static_cast<int>(i));
      continue;
    }
    const Vec3 com = d.R[i] * b.com + d.p[i] - origin;
    const Mat3 I = d.R[i] * fullInertia(b) * d.R[i].transpose();
    fixedMoment_ += b.mass * com;
    fixedYawInertia_ += I(2, 2) + b.mass * (com.x() * com.x() + com.y() * com.y());
  }
  for (const mb::Body& b : m.bodies) baseMass_ += b.mass;
  baseMass_ -= sprung.mass;
  baseMoment_ = fixedMoment_;
  baseYawInertia_ = fixedYawInertia_;
  if (!steered.empty()) {
    // Over the rack travel: the moving bodies' first moment (x, y) and yaw
    // inertia about the base origin, and their angular momentum about its z
    // per rack rate (the steering's own inertia, felt when the rack moves).
    const int carrier = L.wheels[0].carrier != L.base ? L.wheels[0].carrier : L.wheels[1].carrier;
    if (carrier == L.base || m.bodies[carrier].table < 0) refuse("the steered wheels are not the front ones on rack tables");
    const mb::GridAxis rack = m.tables[m.bodies[carrier].table].grid.axisX();
    std::vector<std::vector<double>> samples(4, std::vector<double>(rack.nodes));
    Eigen::VectorXd q = q0, rate = Eigen::VectorXd::Zero(m.nv);
    for (const auto& driven : drivenCoordinates_) rate(driven.second) = 1.0;
    for (int j = 0; j < rack.nodes; ++j) {
      setRackTravel(planar, q, rack.start + j * rack.step);
      mb::updatePositions(m, q, d);
      mb::updateVelocities(m, rate, d);
      double Sx = 0, Sy = 0, J = 0, H = 0;
      for (int i : steered) {
        const mb::Body& b = m.bodies[i];
        const Vec3 com = d.R[i] * b.com + d.p[i] - origin;
        const Vec3 w = d.R[i] * d.vel[i].tail<3>();
        const Vec3 vc = d.R[i] * (d.vel[i].head<3>() + d.vel[i].tail<3>().cross(b.com));
        const Mat3 I = d.R[i] * fullInertia(b) * d.R[i].transpose();
        Sx += b.mass * com.x();
        Sy += b.mass * com.y();
        J += I(2, 2) + b.mass * (com.x() * com.x() + com.y() * com.y());
        H += b.mass * (com.x() * vc.y() - com.y() * vc.x()) + I.row(2).dot(w);
      }
      samples[0][j] = Sx;
      samples[1][j] = Sy;
      samples[2][j] = J;
      samples[3][j] = H;
    }
    steering_ = mb::SplineGrid(rack, mb::GridAxis{0, 1, 1}, samples);
    steered_ = true;
  }
  mb::updatePositions(m, q0, d);

  for (int w = 0; w < 4; ++w) {
    const int sp = L.wheels[w].spindle;
    const mb::Body& b = m.bodies[sp];
    const std::string name = std::string("wheel ") + kCornerNames[w];
    const SpinJoint spin = spinJoint(b, name, "closed-form planar car");
    Wheel& W = wheels_[w];
    W.spinInertia = spin.inertia;
    W.spinSign = spin.sign;
    W.multibodyQ = b.qIndex;
    W.multibodyV = b.vIndex;
    W.centre = d.p[sp] - origin;
    W.axisY = d.R[sp].col(1);
    const int carrier = L.wheels[w].carrier;
    if (carrier == L.base) continue;
    const mb::Body& c = m.bodies[carrier];
    if (c.joint != mb::JointType::Tabulated1 || c.parent != L.base) refuse(name + "'s carrier is not a table of the rack on the base");
    // The wheel's centre and axis over the rack travel, on the carrier table's nodes.
    const mb::GridAxis rack = m.tables[c.table].grid.axisX();
    // And the carrier's rotation about the wheel's axis per rack travel: the
    // steering's share of the wheel's absolute spin rate (what the tyre reads).
    std::vector<std::vector<double>> samples(7, std::vector<double>(rack.nodes));
    Eigen::VectorXd q = q0;
    for (int j = 0; j < rack.nodes; ++j) {
      setRackTravel(planar, q, rack.start + j * rack.step);
      mb::updatePositions(m, q, d);
      const Vec3 centre = d.p[sp] - origin, y = d.R[sp].col(1);
      for (int k = 0; k < 3; ++k) {
        samples[k][j] = centre(k);
        samples[3 + k][j] = y(k);
      }
      samples[6][j] = (d.R[carrier] * d.S.col(c.vIndex).tail<3>()).dot(y);
    }
    W.table = static_cast<int>(tables_.size());
    tables_.emplace_back(rack, mb::GridAxis{0, 1, 1}, samples);
  }
}

void PlanarCar::updateSteering(double t) {
  if (t == steeringTime_) return;
  const mb::SignalValue rack = rackInStep(t);
  steeringTime_ = t;
  // A rack held where it was (a straight, a steady turn) moves nothing.
  if (rack.value == rackNow_.value && rack.rate == rackNow_.rate && rack.accel == rackNow_.accel && steeringValid_) return;
  rackNow_ = rack;
  steeringValid_ = true;
  const double c = rackNow_.value, cd = rackNow_.rate, cdd = rackNow_.accel;
  // Every table is over the rack travel; where their axes agree (the same
  // carrier tables), one lookup of the rack serves them all.
  const mb::SplineGrid* located = nullptr;
  mb::SplineGrid::CurvePoint at;
  auto evalAtRack = [&](const mb::SplineGrid& g, mb::SplineGrid::Curve& s) {
    if (!located || !located->sameAxisX(g)) {
      at = g.curvePoint(c);
      located = &g;
    }
    g.evalCurve(at, s);
  };
  mb::SplineGrid::Curve s;
  if (steered_) {
    // The moving bodies' inertia at the rack travel, and what their motion
    // relative to the base asks of it: d2/dt2 of their first moment (plus
    // the Coriolis share, per yaw rate), d/dt of their angular momentum.
    evalAtRack(steering_, s);
    baseMoment_ = fixedMoment_ + Vec3(s.f[0], s.f[1], 0);
    baseYawInertia_ = fixedYawInertia_ + s.f[2];
    for (int k = 0; k < 2; ++k) {
      steeringForce_(k) = s.ddf[k] * cd * cd + s.df[k] * cdd;
      steeringCoriolis_(k) = 2 * cd * s.df[k];
    }
    steeringYaw_ = s.df[3] * cd * cd + s.f[3] * cdd;
    steeringYawCoriolis_ = s.df[2] * cd;
  }
  for (Wheel& W : wheels_) {
    if (W.table < 0) continue;
    evalAtRack(tables_[W.table], s);
    W.centre = Vec3(s.f[0], s.f[1], s.f[2]);
    W.centreRate = cd * Vec3(s.df[0], s.df[1], s.df[2]);
    W.axisY = Vec3(s.f[3], s.f[4], s.f[5]).normalized();
    W.steeringSpin = cd * s.f[6];
    // The absolute spin's rate of change from the steering (its share above,
    // and the tilt of the axis under the yaw rate), and the tilt's rate.
    W.steeringSpinRate = cdd * s.f[6] + cd * cd * s.df[6];
    W.tiltRate = cd * s.df[5];
  }
}

void PlanarCar::beginStep(double t, const integ::Vec& q, const integ::Vec&) {
  steeringTime_ = std::numeric_limits<double>::quiet_NaN();  // the rack's segment may have changed at a tick
  if (!forces_.needsBeginStep(t)) return;
  updateSteering(t);
  const Heading<double> yaw = headingOf(q(Yaw));
  const Vec3 origin(q(X), q(Y), groundZ_);
  std::array<Vec3, 4> centres, axes;
  for (int w = 0; w < 4; ++w) {
    centres[w] = origin + yaw.toWorld(wheels_[w].centre);
    axes[w] = yaw.toWorld(wheels_[w].axisY);
  }
  forces_.beginContacts(t, centres, axes);
}

integ::EvalStatus PlanarCar::acceptStep(double t, double h, const integ::Vec& q, const integ::Vec& v,
                                        integ::Message& msg) {
  const integ::EvalStatus status = acceptWheels(t, h, q, v, msg);
  if (status != integ::EvalStatus::Ok) return status;
  steeringTime_ = std::numeric_limits<double>::quiet_NaN();
  return integ::EvalStatus::Ok;
}

// The equations of motion by virtual power (Kane's form), in the base frame:
// F = sum over bodies of (partial velocity) . (inertial force - applied force)
// for the sprung body (the only one whose motion relative to the base is a
// state) and the lumped base, plus each wheel's spin about its axis.
// Written for T double (the residual: it also keeps the wheels' kinematics,
// the tyres' outputs and the corner springs for the step's acceptance, the
// fast columns and telemetry) and T ad::Dual (the Jacobian: nothing kept).
template <typename T>
void PlanarCar::equations(double t, const T* q, const T* v, const integ::Vec& a, T* F) {
  constexpr bool kKeep = std::is_same_v<T, double>;
  using V3 = Vec3T<T>;
  using M3 = Mat3T<T>;
  updateSteering(t);
  const double h = forces_.sinceAccepted(t);
  const PlanarLoads& PL = *vehicle_.planar;
  const VehicleSpec& spec = vehicle_.spec;
  const Heading<T> yaw = headingOf(q[Yaw]);
  const M3 RJ = rollPitch(q[Roll], q[Pitch]);
  const bool lift = spec.liftAreaFront != 0 || spec.liftAreaRear != 0;
  M3 Rs;  // the sprung body's axes in the base frame (what the bars and the lift need)
  if (lift || !spec.antiRollBars.empty()) Rs.noalias() = RJ * sprungRest_;
  const V3 e = RJ.col(1);  // the pitch axis
  const T u = v[0], vs = v[1], r = v[2], rollRate = v[3], pitchRate = v[4];
  const V3 rho = RJ * comArm0_, P = axisPoint_ + rho;
  const V3 omegaRel = rollRate * kX + pitchRate * e, omega = r * kZ + omegaRel;
  const V3 g = yaw.toLocal(gravity_.cast<T>());
  auto sprungPoint = [&](const Vec3& body) -> V3 { return axisPoint_ + Rs * (body - jointInBody_); };

  // Applied forces: on the sprung body as a wrench about its centre of mass,
  // on the lumped base (wheels' centres included) as a force and a yaw
  // moment about the base origin, on each spin coordinate.
  V3 fs = sprungMass_ * g, ts = V3::Zero();
  V3 fb = baseMass_ * g;
  T tb = T(0.0);
  std::array<T, 4> Qspin{T(0.0), T(0.0), T(0.0), T(0.0)};
  auto onSprung = [&](const V3& x, const V3& f) {
    fs += f;
    ts += (x - P).cross(f);
  };
  auto onBase = [&](const V3& x, const V3& f) {
    fb += f;
    tb += x.x() * f.y() - x.y() * f.x();
  };

  // Corner springs between the rolled and pitched body and the base (their
  // reaction on the base is vertical: no work in the plane).
  std::array<T, 4> load, travel;
  for (int w = 0; w < 4; ++w) {
    const V3 ps = axisPoint_ + RJ * cornerArm_[w];
    const T z = ps.z() - PL.basePoint[w].z();
    const T zd = omegaRel.cross(V3(ps - axisPoint_)).z();
    travel[w] = -PL.suspensionShare[w] * z;
    const T spring = -PL.rate[w] * z, damper = -PL.damping[w] * zd;
    if constexpr (kKeep) {
      WheelOutput& o = forces_.output(w);
      o.cornerSpring = spring;
      o.cornerDamper = damper;
    }
    const T f = spring + damper;
    onSprung(ps, V3(f * kZ));
    load[w] = PL.staticLoad[w] + f;
  }
  const std::array<T, 4> shift = forces_.planarLoadShift(V3(yaw.c, yaw.s, T(0.0)), V3(-yaw.s, yaw.c, T(0.0)));
  for (int w = 0; w < 4; ++w) load[w] += shift[w];
  if (!spec.antiRollBars.empty()) {
    const V3 up = Rs.col(2);
    auto centreTravel = [&](int w) -> T {
      return (Rs.transpose() * (wheels_[w].centre - axisPoint_) + jointInBody_).z() - vehicle_.layout.wheelCentreAtDesign[w].z();
    };
    for (const AntiRollBarSpec& bar : spec.antiRollBars) {
      const T f = PL.barRate[bar.left / 2] * (centreTravel(bar.left) - centreTravel(bar.right));
      for (const auto& [w, sign] : {std::pair{bar.left, 1.0}, std::pair{bar.right, -1.0}}) {
        onBase(wheels_[w].centre.template cast<T>(), V3(-sign * f * up));
        onSprung(wheels_[w].centre.template cast<T>(), V3(sign * f * up));
        load[w] += sign * f;
      }
    }
  }

  // The wheels: tyres on their contact planes, brakes, drive torques.
  const V3 origin(q[X], q[Y], T(groundZ_));
  std::array<V3, 4> tyreAxis;
  std::array<T, 4> relativeSpin;
  std::array<tyre::WheelKinematicsT<T>, 4> ks;
  for (int w = 0; w < 4; ++w) {
    const Wheel& W = wheels_[w];
    V3 axis = RJ * W.axisY;  // the tyre sees the body's roll and pitch and the carrier's turn over its travel
    axis += V3(travel[w] * (RJ * turnPerTravel_[w])).cross(axis);
    axis.normalize();
    tyre::WheelKinematicsT<T>& k = ks[w];
    k.centre = origin + yaw.toWorld(W.centre.cast<T>());
    k.spinAxis = yaw.toWorld(axis);
    k.centreVelocity = yaw.toWorld(V3(V3(u - r * W.centre.y(), vs + r * W.centre.x(), T(0.0)) + W.centreRate));
    const T jointRate = v[Spin + w];
    k.spinRate = r * W.axisY.z() + W.steeringSpin + W.spinSign * jointRate;  // about the wheel's y
    relativeSpin[w] = W.spinSign * jointRate;
    if constexpr (kKeep) forces_.output(w).modelLoad = load[w];
    tyre::TyreOutputT<T> dual;
    const tyre::TyreOutputT<T>& tyre = wheelTyre(w, k, relativeSpin[w], h, std::optional<T>(load[w]), dual);
    const Vec3 spinAxis = W.spinSign * W.axisY;  // the spin joint's
    if (tyre.inContact) {
      const V3 Ft = yaw.toLocal(tyre.force), M = yaw.toLocal(tyre.moment);
      const V3 at = yaw.toLocal(V3(tyre.point - origin));
      onBase(at, Ft);
      tb += M.z();
      Qspin[w] += spinAxis.dot(V3(V3(at - W.centre).cross(Ft) + M));
    }
    Qspin[w] += W.spinSign * forces_.brakeTorque(w, relativeSpin[w], h);
    tyreAxis[w] = axis;
  }
  if constexpr (kKeep) {
    turn_ = {yaw.c, yaw.s};
    origin_ = origin;
    pitchAxis_ = e;
    tyreAxis_ = tyreAxis;
  }
  // Drive torques: a powertrain's from its driveline at the crank's and the
  // wheels' speeds now (the crank's own torque: the engine's less the
  // clutch's), or as the driver holds them.
  const DriveTorques<T> drive = driveTorques(engineV_ >= 0 ? v[Engine] : T(0.0), relativeSpin, h);
  for (int w = 0; w < 4; ++w) {
    if (ad::value(drive.wheel[w]) == 0.0) continue;
    const Wheel& W = wheels_[w];
    if (spec.driveReaction == DriveReaction::Carrier) {
      Qspin[w] += W.spinSign * drive.wheel[w];
      continue;
    }
    const V3 torque = drive.wheel[w] * tyreAxis[w];
    tb += torque.z();
    Qspin[w] += W.spinSign * W.axisY.dot(torque);
    if (spec.driveReaction == DriveReaction::Chassis) ts -= torque;
  }

  // Air: drag at the sprung body's centre of mass, lift above the axles.
  const V3 vc = u * kX + vs * kY + r * kZ.cross(P) + omegaRel.cross(rho);
  if (spec.dragArea > 0) onSprung(P, V3(-spec.dragArea * ad::norm0(vc) * vc));
  if (lift) {
    const T air = Rs.col(0).dot(vc);
    const Vec3& com = vehicle_.model.bodies[vehicle_.layout.chassis].com;
    for (int axle = 0; axle < 2; ++axle) {
      const Vec3 centre = 0.5 * (vehicle_.layout.wheelCentreAtDesign[2 * axle] + vehicle_.layout.wheelCentreAtDesign[2 * axle + 1]);
      const double area = axle == 0 ? spec.liftAreaFront : spec.liftAreaRear;
      onSprung(sprungPoint(Vec3(centre.x(), com.y(), com.z())), V3(area * air * air * Rs.col(2)));
    }
  }

  // Inertial forces. The sprung body: partial velocities of its centre of
  // mass and partial angular velocities for (forward, sideways, yaw rate,
  // roll rate, pitch rate); accelerations = partials . a + velocity terms.
  const std::array<V3, 5> Jv{V3(kX), V3(kY), V3(kZ.cross(P)), V3(kX.cross(rho)), V3(e.cross(rho))};
  const std::array<V3, 5> Jw{V3::Zero(), V3::Zero(), V3(kZ), V3(kX), e};
  const V3 xe = kX.cross(e);
  V3 ac = omega.cross(omegaRel.cross(rho)) + (rollRate * pitchRate) * xe.cross(rho) + r * kZ.cross(vc);
  V3 alpha = (rollRate * pitchRate) * xe + r * kZ.cross(omegaRel);
  for (int j = 0; j < 5; ++j) {
    ac += a(j) * Jv[j];
    alpha += a(j) * Jw[j];
  }
  const M3 I = RJ * inertia0_ * RJ.transpose();
  const V3 fin = sprungMass_ * ac - fs;
  V3 tin = I * alpha + omega.cross(V3(I * omega)) - ts;
  if (engineV_ >= 0) {
    // The crank's rotor: d/dt of its angular momentum I (x . w_e) x about
    // the body's x axis, w_e = w + crank rate x.
    const V3 ax = RJ * crankAxis0_;
    const T spin = ax.dot(omega) + v[Engine], spinRate = ax.dot(alpha) + a(Engine);
    tin += engineInertia_ * (spinRate * ax + spin * omega.cross(ax));
    F[Engine] = engineInertia_ * spinRate - drive.crank;
  }
  for (int j = 0; j < 5; ++j) F[j] = Jv[j].dot(fin) + Jw[j].dot(tin);
  // The lumped base: its centre of mass accelerates with the base frame.
  const T Ax = a(0) - r * vs, Ay = a(1) + r * u;
  const double Sx = baseMoment_.x(), Sy = baseMoment_.y();
  F[0] += baseMass_ * Ax - a(2) * Sy - r * r * Sx - fb.x() + steeringForce_.x() - r * steeringCoriolis_.y();
  F[1] += baseMass_ * Ay + a(2) * Sx - r * r * Sy - fb.y() + steeringForce_.y() + r * steeringCoriolis_.x();
  F[2] += Sx * Ay - Sy * Ax + baseYawInertia_ * a(2) - tb + steeringYaw_ + r * steeringYawCoriolis_;
  // The spins: the absolute spin about the wheel's axis (Euler's equation of
  // a wheel symmetric about it), coupled to the yaw and the steering.
  for (int w = 0; w < 4; ++w) {
    const Wheel& W = wheels_[w];
    const double coupling = W.spinInertia * W.axisY.z() * W.spinSign;
    F[Spin + w] = W.spinInertia * a(Spin + w) + coupling * a(2) - Qspin[w] +
                  W.spinSign * W.spinInertia * (W.steeringSpinRate + r * W.tiltRate);
    F[2] += coupling * a(Spin + w) + W.spinInertia * ks[w].spinRate * W.tiltRate;
  }
}

template void PlanarCar::equations(double, const double*, const double*, const integ::Vec&, double*);
template void PlanarCar::equations(double, const ad::Dual*, const ad::Dual*, const integ::Vec&, ad::Dual*);

bool PlanarCar::massMatrix(double t, const integ::Vec& q, integ::Mat& Fa) {
  updateSteering(t);
  const Mat3 RJ = rollPitch(q(Roll), q(Pitch));
  const Vec3 e = RJ.col(1), rho = RJ * comArm0_, P = axisPoint_ + rho;
  const std::array<Vec3, 5> Jv{kX, kY, kZ.cross(P), kX.cross(rho), e.cross(rho)};
  const std::array<Vec3, 5> Jw{Vec3::Zero(), Vec3::Zero(), kZ, kX, e};
  const Mat3 I = RJ * inertia0_ * RJ.transpose();
  Fa.setZero(n_, n_);
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) Fa(j, k) = sprungMass_ * Jv[j].dot(Jv[k]) + Jw[j].dot(I * Jw[k]);
  if (engineV_ >= 0) {
    const Vec3 ax = RJ * crankAxis0_;
    Fa(Engine, Engine) = engineInertia_;
    for (int j = 0; j < 5; ++j) {
      Fa(Engine, j) = Fa(j, Engine) = engineInertia_ * ax.dot(Jw[j]);
      for (int k = 0; k < 5; ++k) Fa(j, k) += engineInertia_ * ax.dot(Jw[j]) * ax.dot(Jw[k]);
    }
  }
  Fa(0, 0) += baseMass_;
  Fa(1, 1) += baseMass_;
  Fa(0, 2) -= baseMoment_.y();
  Fa(2, 0) -= baseMoment_.y();
  Fa(1, 2) += baseMoment_.x();
  Fa(2, 1) += baseMoment_.x();
  Fa(2, 2) += baseYawInertia_;
  for (int w = 0; w < 4; ++w) {
    const Wheel& W = wheels_[w];
    Fa(Spin + w, Spin + w) = W.spinInertia;
    Fa(2, Spin + w) = Fa(Spin + w, 2) = W.spinInertia * W.axisY.z() * W.spinSign;
  }
  return true;
}

void PlanarCar::toMultibody(double t, const integ::Vec& q, const integ::Vec& v, integ::Vec& qm, integ::Vec& vm) const {
  const mb::Model& m = vehicle_.model;
  const VehicleLayout& L = vehicle_.layout;
  qm = mb::neutralPositions(m);
  vm.setZero(m.nv);
  const int bq = m.bodies[L.base].qIndex, bv = m.bodies[L.base].vIndex;
  const int sq = m.bodies[L.chassis].qIndex, sv = m.bodies[L.chassis].vIndex;
  qm.segment<3>(bq) = q.head<3>();
  vm.segment<3>(bv) = v.head<3>();
  qm.segment<2>(sq) = q.segment<2>(Roll);
  vm.segment<2>(sv) = v.segment<2>(Roll);
  for (int w = 0; w < 4; ++w) {
    qm(wheels_[w].multibodyQ) = q(Spin + w);
    vm(wheels_[w].multibodyV) = v(Spin + w);
  }
  if (engineV_ >= 0) {
    qm(engineQ_) = q(Engine);
    vm(engineV_) = v(Engine);
  }
  driveMultibody(t, qm, vm);
}

Vec3 PlanarCar::chassisOrigin(const integ::Vec& q) const {
  const Heading<double> yaw = headingOf(q(Yaw));
  const Vec3 p = axisPoint_ - rollPitch(q(Roll), q(Pitch)) * sprungRest_ * jointInBody_;
  return Vec3(q(X), q(Y), groundZ_) + yaw.toWorld(p);
}

void PlanarCar::fromMultibody(const integ::Vec& qm, const integ::Vec& vm, integ::Vec& q, integ::Vec& v) const {
  const mb::Model& m = vehicle_.model;
  const VehicleLayout& L = vehicle_.layout;
  q.resize(n_);
  v.resize(n_);
  const int bq = m.bodies[L.base].qIndex, bv = m.bodies[L.base].vIndex;
  const int sq = m.bodies[L.chassis].qIndex, sv = m.bodies[L.chassis].vIndex;
  q.head<3>() = qm.segment<3>(bq);
  v.head<3>() = vm.segment<3>(bv);
  q.segment<2>(Roll) = qm.segment<2>(sq);
  v.segment<2>(Roll) = vm.segment<2>(sv);
  for (int w = 0; w < 4; ++w) {
    q(Spin + w) = qm(wheels_[w].multibodyQ);
    v(Spin + w) = vm(wheels_[w].multibodyV);
  }
  if (engineV_ >= 0) {
    q(Engine) = qm(engineQ_);
    v(Engine) = vm(engineV_);
  }
}

// As the residual takes them: the tyre's force and yaw moment on the base,
// the moment about the spin axis on the spin.
void PlanarCar::addTyreForces(int w, const tyre::TyreOutput& tyre, double scale, Eigen::Ref<integ::Vec> col) const {
  if (!tyre.inContact) return;
  const Wheel& W = wheels_[w];
  const Vec3 F = scale * turn_.toLocal(tyre.force), M = scale * turn_.toLocal(tyre.moment);
  const Vec3 at = turn_.toLocal(tyre.point - origin_);
  col(X) -= F.x();
  col(Y) -= F.y();
  col(Yaw) -= at.x() * F.y() - at.y() * F.x() + M.z();
  col(Spin + w) -= (W.spinSign * W.axisY).dot((at - W.centre).cross(F) + M);
}

void PlanarCar::addDriveTorque(int w, double scale, Eigen::Ref<integ::Vec> col) const {
  const Wheel& W = wheels_[w];
  const DriveReaction reaction = vehicle_.spec.driveReaction;
  if (reaction == DriveReaction::Carrier) {
    col(Spin + w) -= scale * W.spinSign;
    return;
  }
  const Vec3 torque = scale * tyreAxis_[w];  // on the wheel about its tyre's axis (its z share on the base, the wheel rides on it)
  col(Yaw) -= torque.z();
  col(Spin + w) -= W.spinSign * W.axisY.dot(torque);
  if (reaction != DriveReaction::Chassis) return;
  // The sprung body takes it back: on its yaw, roll and pitch partials.
  col(Yaw) += torque.z();
  col(Roll) += torque.x();
  col(Pitch) += pitchAxis_.dot(torque);
}

}  // namespace bdfcar::vehicle
