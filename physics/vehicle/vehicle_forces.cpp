#include "vehicle/vehicle_forces.h"

#include "autodiff.h"

#include <algorithm>
#include <cmath>
#include "multibody/dynamics.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

namespace {
// Forward-difference increment of a spin rate (rad/s): sqrt(machine
// epsilon), scaled with the rate, as the integrator's own columns.
constexpr double kFiniteDifferenceStep = 1.5e-8;
}  // namespace

VehicleForces::VehicleForces(const Vehicle& vehicle, const terrain::Terrain& terrain,
                             const TerrainContactOptions& options)
    : vehicle_(vehicle),
      terrain_(terrain),
      options_(options),
      tyres_{tyre::Tyre(vehicle.wheel(0).tyre), tyre::Tyre(vehicle.wheel(1).tyre), tyre::Tyre(vehicle.wheel(2).tyre),
             tyre::Tyre(vehicle.wheel(3).tyre)} {
  for (int w = 0; w < 4; ++w)
    if (vehicle.wheel(w).driven) driven_.push_back(w);
  // The cams' lengths from each tyre where the file leaves them: the static
  // contact length at a quarter of the car's weight.
  double mass = 0;
  for (const BodySpec& b : vehicle.spec.bodies) mass += b.mass;
  const double quarterWeight = 0.25 * mass * std::abs(vehicle.model.gravity.z());
  double spacing = INFINITY;
  for (int w = 0; w < 4; ++w) {
    const tyre::TyreParams& p = vehicle.wheel(w).tyre;
    envelopes_[w] = tyre::resolveEnvelope(tyre::contact(p), tyre::unloadedRadius(p), tyre::verticalStiffness(p), quarterWeight);
    if (envelopes_[w].on) spacing = std::min(spacing, envelopes_[w].spacing);
  }
  if (std::isfinite(spacing)) lattice_.emplace(terrain, spacing);
  for (int w = 0; w < 4; ++w) pointContacts_ = pointContacts_ || (options_.groundInsideStep && !groundFollowsWheel(w));
}

void VehicleForces::reset(double t) {
  for (WheelContact& c : state_->wheels) {
    c.slip = tyre::SlipState{};
    c.brakeDeflection = 0;
    c.acceptedForce.setZero();
    c.acceptedInContact = false;
    c.acceptedFx = c.acceptedFy = c.acceptedFz = 0;
  }
  state_->driveline.clutchDeflection = 0;
  state_->lastAccepted = t;
  state_->planesReady = false;
  if (lattice_) lattice_->clear();
}

tyre::WheelKinematics VehicleForces::wheelKinematics(const mb::Data& d, int w) const {
  const int b = vehicle_.layout.wheels[w].spindle;
  tyre::WheelKinematics k;
  k.centre = d.p[b];
  k.spinAxis = d.R[b].col(1);
  k.centreVelocity = d.R[b] * d.vel[b].head<3>();
  k.spinRate = d.vel[b].tail<3>()(1);  // body-frame angular velocity about the spindle y axis
  return k;
}

double VehicleForces::relativeSpin(const mb::Data& d, int w) const {
  // Angular velocity of the spindle relative to its carrier, about the spindle's y (spin) axis.
  const WheelLayout& wl = vehicle_.layout.wheels[w];
  const Eigen::Vector3d rel = d.vel[wl.spindle].tail<3>() - d.Xup[wl.spindle].E * d.vel[wl.carrier].tail<3>();
  return rel.y();
}

tyre::ContactPlane VehicleForces::queryGround(const Eigen::Vector3d& centre, const Eigen::Vector3d& spinAxis,
                                              double R0) const {
  tyre::ContactPlane plane;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const double reach = 2.0 * R0 + 0.5;
  if (options_.raysPerWheel <= 1) {
    const terrain::Hit h = terrain_.castRay(centre + R0 * up, -up, reach);
    if (!h.hit) return plane;
    plane.valid = true;
    plane.point = h.point;
    plane.normal = h.normal;
    plane.friction = h.friction;
    return plane;
  }
  // Envelope: rays along the wheel heading; the ground point deepest inside
  // the wheel circle defines the plane, with its normal pointing from that
  // point to the wheel centre (a curb edge pushes the wheel up and back).
  Eigen::Vector3d heading = spinAxis.cross(up);
  if (heading.squaredNorm() < 1e-6) heading = Eigen::Vector3d::UnitX();
  heading.normalize();
  double best = -1e9;
  for (int i = 0; i < options_.raysPerWheel; ++i) {
    const double s = -1.0 + 2.0 * i / (options_.raysPerWheel - 1);
    const Eigen::Vector3d from = centre + s * options_.footprintHalfLength * R0 * heading + R0 * up;
    const terrain::Hit h = terrain_.castRay(from, -up, reach);
    if (!h.hit) continue;
    Eigen::Vector3d r = centre - h.point;
    r -= r.dot(spinAxis) * spinAxis;  // in the wheel plane
    const double penetration = R0 - r.norm();
    // Prefer the central ray on equal footing (flat ground).
    const double score = penetration - 1e-9 * std::abs(s);
    if (score > best) {
      best = score;
      plane.valid = true;
      plane.point = h.point;
      plane.friction = h.friction;
      plane.normal = (std::abs(s) < 1e-12 || r.norm() < 1e-9) ? h.normal : Eigen::Vector3d(r.normalized());
      if (plane.normal.dot(h.normal) < 0.2) plane.normal = h.normal;
    }
  }
  return plane;
}

void VehicleForces::prepareGround(int w, const Eigen::Vector3d& centre, const Eigen::Vector3d& spinAxis,
                                  const Eigen::Vector3d& travel) {
  WheelContact& c = state_->wheels[w];
  if (!envelopes_[w].on) {
    c.plane = queryGround(centre, spinAxis, tyres_[w].unloadedRadius());
    return;
  }
  sampleProfile(w, centre, spinAxis, travel);
  c.plane = tyre::effectivePlane(envelopes_[w], c.profile, centre);
}

void VehicleForces::sampleProfile(int w, const Eigen::Vector3d& centre, const Eigen::Vector3d& spinAxis,
                                  const Eigen::Vector3d& travel) {
  const tyre::Envelope& e = envelopes_[w];
  tyre::RoadProfile& p = state_->wheels[w].profile;
  const double R0 = tyres_[w].unloadedRadius();
  // The level shortcut is tried where the last step's road was level (or at
  // the start): on relief its ray and the terrain's check would be wasted.
  const bool wasLevel = !p.valid || (p.linear && std::abs(p.slope) < 1e-9);
  Eigen::Vector2d heading = spinAxis.cross(Eigen::Vector3d::UnitZ()).head<2>();
  p.heading = heading.squaredNorm() < 1e-6 ? Eigen::Vector2d::UnitX() : Eigen::Vector2d(heading.normalized());
  p.origin = centre.head<2>();
  // Both cams' reach, and a margin for where the step ends up against its
  // prediction (millimetres; a lattice node more is plenty), around the
  // wheel's whole path in the step on both sides of the predicted end: as
  // far again as the wheel moves in the predicted step, ahead (the next
  // may be twice as long: a split step's halves grow back by doubling) and
  // behind (a step refined into halves, and the pieces after them, end
  // short of the predicted end and keep this profile: at a 30 ms step, 80
  // km/h, a quarter piece ended 0.5 m short, its cams off the profile).
  terrain::HeightLattice& lattice = *lattice_;
  const double half = 0.5 * e.base + e.a + 2.0 * lattice.spacing();
  const int halfCount = std::min(tyre::RoadProfile::kCapacity / 2 - 1,
                                 static_cast<int>(std::ceil(half / lattice.spacing())));
  p.ds = half / halfCount;
  const double along = std::abs(travel.head<2>().dot(p.heading));
  // Samples on each side of the origin's; where the path and the cams need
  // more than the profile holds (a long step at speed, long cams on a fine
  // lattice), fewer and further apart: the whole path stays covered.
  constexpr int kMostPerSide = (tyre::RoadProfile::kCapacity - 1) / 2;
  int perSide = halfCount + static_cast<int>(std::ceil(along / p.ds));
  if (perSide > kMostPerSide) {
    perSide = kMostPerSide;
    p.ds = (half + along) / perSide;
  }
  // Samples past n stay zero (a state restored from its bytes has them so).
  const int n = 2 * perSide + 1;
  if (n < p.n) {
    std::fill(p.z.begin() + n, p.z.begin() + p.n, 0.0);
    std::fill(p.cross.begin() + n, p.cross.begin() + p.n, 0.0);
  }
  p.n = n;
  const int behind = perSide;  // samples before the origin's
  p.s0 = -behind * p.ds;
  p.valid = false;
  const double zTop = centre.z() + R0, reach = 2.0 * R0 + 0.5;
  if (wasLevel && levelProfile(p, zTop, reach)) return;
  terrain::HeightLattice::Point at;
  for (int k = 0; k < p.n; ++k) {
    const Eigen::Vector2d xy = p.origin + (p.s0 + k * p.ds) * p.heading;
    if (!lattice.at(xy.x(), xy.y(), zTop, reach, at)) {
      p.z[k] = tyre::RoadProfile::kNoGround;
      p.cross[k] = 0;
      continue;
    }
    // The friction under the wheel, or of the first ground before it where
    // the centre finds none (never the last step's).
    if (k == behind || !p.valid) p.friction = at.friction;
    p.valid = true;
    p.z[k] = at.z;
    p.cross[k] = -p.heading.y() * at.dzdx + p.heading.x() * at.dzdy;
  }
  tyre::findLine(p);
}

bool VehicleForces::levelProfile(tyre::RoadProfile& p, double zTop, double reach) const {
  // Most road is level: one ray under the line's origin and the terrain's
  // word that the box around the whole line is level there (to 1 um) fill
  // the profile without the lattice (terrain.h, levelOver).
  const terrain::Hit h = terrain_.castRay(Eigen::Vector3d(p.origin.x(), p.origin.y(), zTop), -Eigen::Vector3d::UnitZ(), reach);
  if (!h.hit) return false;
  terrain::Terrain::LevelQuery q;
  const Eigen::Vector2d a = p.origin + p.s0 * p.heading, b = p.origin + (p.s0 + (p.n - 1) * p.ds) * p.heading;
  q.lo = a.cwiseMin(b);
  q.hi = a.cwiseMax(b);
  q.zTop = zTop;
  q.zBottom = zTop - reach;
  q.height = h.point.z();
  q.tolerance = 1e-6;
  q.minNormalZ = 1.0;
  if (!terrain_.levelOver(q)) return false;
  std::fill(p.z.begin(), p.z.begin() + p.n, q.height);
  std::fill(p.cross.begin(), p.cross.begin() + p.n, 0.0);
  p.friction = h.friction;
  p.valid = true;
  p.linear = true;
  p.slope = 0;
  return true;
}

const tyre::ContactPlane& VehicleForces::groundAt(int w, const Eigen::Vector3d& centre) {
  const WheelContact& c = state_->wheels[w];
  if (!groundFollowsWheel(w)) return c.plane;
  insideStep_[w] = tyre::effectivePlane(envelopes_[w], c.profile, centre);
  return insideStep_[w];
}

const tyre::ContactPlane& VehicleForces::latestGround(int w) const {
  const WheelContact& c = state_->wheels[w];
  return groundFollowsWheel(w) ? insideStep_[w] : c.plane;
}

// Each spin's column by a forward difference of its wheel's tyre and brake
// alone (the spin moves the spindle alone: its motion subspace S), the
// tyre's wrench change taken to the joints along the path to the root. The
// tyre's and brake's inputs are those of the last apply(), as are outputs_.
VehicleForces::SpinPoint VehicleForces::spinPoint(const mb::Data& d, double t) const {
  SpinPoint p;
  p.h = sinceAccepted(t);
  for (int w = 0; w < 4; ++w) {
    p.ks[w] = wheelKinematics(d, w);
    if (vehicle_.planar) planarWheelAttitude(d, w, p.ks[w]);
    p.spins[w] = relativeSpin(d, w);
  }
  p.driveline = vehicle_.spec.powertrain.has_value();
  p.engine = p.driveline ? engineSpeed(d) : 0.0;
  if (p.driveline) p.T0 = drivelineAt(p.engine, p.spins, p.h);
  return p;
}

// The change of F (a residual's, F = M a - Q) by wheel w's tyre, brake and
// driveline when its spin's joint rate moves by dv, divided by per (dv: the
// column's slope; 1: the change itself).
void VehicleForces::addSpinChange(const mb::Model& model, const mb::Data& d, const SpinPoint& p, int w, double dv,
                                  double per, Eigen::Ref<Eigen::VectorXd> part) const {
  const WheelLayout& wl = vehicle_.layout.wheels[w];
  const mb::Vec6 s = d.S.col(wl.spinV);  // the spindle's body-frame motion per unit joint rate
  tyre::WheelKinematics k = p.ks[w];
  k.centreVelocity += d.R[wl.spindle] * (dv * s.head<3>());
  k.spinRate += dv * s(4);  // about the spindle's y
  const tyre::TyreOutput& base = outputs_[w].out;
  const tyre::TyreOutput moved = tyreAt(w, k, p.h);
  mb::Vec6 df = mb::Vec6::Zero();
  if (moved.inContact) df += mb::bodyWrench(d, wl.spindle, moved.point, moved.force, moved.moment);
  if (base.inContact) df -= mb::bodyWrench(d, wl.spindle, base.point, base.force, base.moment);
  // F = tau - jointForce, and tau holds -S^T X^T fext.
  mb::addPathJointForces(model, d, wl.spindle, df, -1.0 / per, part);
  const double spin = p.spins[w];
  part(wl.spinV) -= wl.spinSign * (brakeTorque(w, spin + dv * s(4), p.h) - brakeTorque(w, spin, p.h)) / per;
  // A driven wheel's spin moves the differential's output speed and the
  // clutch's slip: every driven wheel's drive torque and the crank's.
  if (!p.driveline || std::find(driven_.begin(), driven_.end(), w) == driven_.end()) return;
  std::array<double, 4> movedSpins = p.spins;
  movedSpins[w] += dv * s(4);
  const DrivelineTorques T1 = drivelineAt(p.engine, movedSpins, p.h);
  part(vehicle_.layout.engineV) -= ((T1.engine - T1.clutch) - (p.T0.engine - p.T0.clutch)) / per;
  for (int u : driven_) addDriveTorqueColumn(model, d, u, p.ks[u], (T1.drive[u] - p.T0.drive[u]) / per, part);
}

void VehicleForces::addFastColumnParts(const mb::Model& model, const mb::Data& d, double t,
                                       const std::vector<int>& columns, Eigen::MatrixXd& parts) {
  const SpinPoint p = spinPoint(d, t);
  for (int w = 0; w < 4; ++w) {
    const auto col = std::find(columns.begin(), columns.end(), vehicle_.layout.wheels[w].spinV);
    if (col == columns.end()) continue;
    const double dv = spinIncrement(p.ks[w].spinRate);
    addSpinChange(model, d, p, w, dv, dv, parts.col(static_cast<int>(col - columns.begin())));
  }
}

bool VehicleForces::addFastRowChange(const mb::Model& model, const mb::Data& d, double t, int column, double dv,
                                     double& change) {
  for (int w = 0; w < 4; ++w) {
    if (vehicle_.layout.wheels[w].spinV != column) continue;
    rowScratch_.setZero(model.nv);
    addSpinChange(model, d, spinPoint(d, t), w, dv, 1.0, rowScratch_);
    change += rowScratch_(column);
    return true;
  }
  return false;
}

tyre::TyreOutput VehicleForces::tyreAt(int w, const tyre::WheelKinematics& k, double h) const {
  return tyres_[w].evaluate(k, latestGround(w), state_->wheels[w].slip, h, modelLoad(w));
}

double VehicleForces::spinIncrement(double spinRate) { return kFiniteDifferenceStep * std::max(1.0, std::abs(spinRate)); }

void VehicleForces::beginStep(const mb::Model&, const mb::Data& d, double t) {
  // Positions only are current here.
  std::array<Eigen::Vector3d, 4> centres, axes;
  for (int w = 0; w < 4; ++w) {
    const int b = vehicle_.layout.wheels[w].spindle;
    centres[w] = d.p[b];
    axes[w] = d.R[b].col(1);
  }
  beginContacts(t, centres, axes);
}

void VehicleForces::beginContacts(double t, const std::array<Eigen::Vector3d, 4>& centres,
                                  const std::array<Eigen::Vector3d, 4>& spinAxes) {
  // A run's first planes serve its first step wherever that ends (cast at
  // its start or at its predicted end, as the model calls this).
  const bool first = !state_->planesReady;
  for (int w = 0; w < 4; ++w)
    if (first || !groundFollowsWheel(w)) prepareGround(w, centres[w], spinAxes[w]);
  state_->planesReady = true;
  state_->planesFor = first ? kAnyStep : t;
}

template <typename T>
T VehicleForces::brakeTorque(int w, const T& spin, double h) const {
  const WheelContact& c = state_->wheels[w];
  if (c.brakeCapacity <= 0) return T(0.0);
  // Spring-damper on the spin since the wheel last slipped, saturated smoothly
  // at the available torque (a kink would make Newton cycle at the limit).
  const T t = kBrakeStiffness * (c.brakeDeflection + h * spin) + kBrakeDamping * spin;
  return -c.brakeCapacity * pm::tanh(T(t / c.brakeCapacity));
}

template <typename T>
void VehicleForces::tyreForce(int w, const tyre::WheelKinematicsT<T>& k, double h, std::optional<T> load,
                              tyre::TyreOutputT<T>& out) const {
  const WheelContact& c = state_->wheels[w];
  tyre::ContactPlaneT<T> ground;
  if (groundFollowsWheel(w)) {  // as groundAt, in T
    ground = tyre::effectivePlane(envelopes_[w], c.profile, k.centre);
  } else {
    ground.valid = c.plane.valid;
    ground.point = c.plane.point.cast<T>();
    ground.normal = c.plane.normal.cast<T>();
    ground.friction = c.plane.friction;
  }
  tyres_[w].evaluate(k, ground, c.slip, h, load, out);
}

void VehicleForces::planarLoads(mb::Data& d) {
  const PlanarLoads& P = *vehicle_.planar;
  const int base = vehicle_.layout.base, sprung = vehicle_.layout.chassis;
  const Eigen::Vector3d up = d.R[base].col(2);
  // Corner springs: the sprung body's height over each corner relative to the base.
  for (int w = 0; w < 4; ++w) {
    const Eigen::Vector3d ps = mb::pointPosition(d, sprung, P.sprungPoint[w]);
    const Eigen::Vector3d pb = mb::pointPosition(d, base, P.basePoint[w]);
    const double z = up.dot(ps - pb);
    const double zd = up.dot(mb::pointVelocity(d, sprung, P.sprungPoint[w]) - mb::pointVelocity(d, base, P.basePoint[w]));
    cornerTravel_[w] = -P.suspensionShare[w] * z;
    outputs_[w].cornerSpring = -P.rate[w] * z;
    outputs_[w].cornerDamper = -P.damping[w] * zd;
    const double f = outputs_[w].cornerSpring + outputs_[w].cornerDamper;  // + pushes the body up and the tyre down
    mb::addWorldForce(d, sprung, ps, f * up);
    mb::addWorldForce(d, base, pb, -f * up);
    outputs_[w].modelLoad = P.staticLoad[w] + f;
  }
  // The roll centres: each axle's lateral tyre force at its roll-centre
  // height, the longitudinal ones at the axis height. The tyre forces are
  // those of the last accepted step, advanced once per step as the brake
  // spring is: a step's lag on a fifth of the load transfer, where a second
  // tyre evaluation per residual would cost a fifth of the step (RESULTS 6b).
  const std::array<double, 4> shift = planarLoadShift<double>(d.R[base].col(0), d.R[base].col(1));
  for (int w = 0; w < 4; ++w) outputs_[w].modelLoad += shift[w];
}

template <typename T>
std::array<T, 4> VehicleForces::planarLoadShift(const tyre::Vec3T<T>& forward, const tyre::Vec3T<T>& left) const {
  const PlanarLoads& P = *vehicle_.planar;
  T lateral[2] = {T(0.0), T(0.0)}, longitudinal = T(0.0);
  for (int w = 0; w < 4; ++w) {
    lateral[w / 2] += left.dot(state_->wheels[w].acceptedForce);
    longitudinal += forward.dot(state_->wheels[w].acceptedForce);
  }
  std::array<T, 4> out{T(0.0), T(0.0), T(0.0), T(0.0)};
  for (int a = 0; a < 2; ++a) {
    const T shift = lateral[a] * P.rollCentreHeight[a] / P.track[a];  // onto the right wheel in a left turn
    out[2 * a] = -shift;
    out[2 * a + 1] = shift;
  }
  const T pitch = 0.5 * longitudinal * P.axisHeight / P.wheelbase;  // onto the rear when driving
  for (int w = 0; w < 4; ++w) out[w] += w < 2 ? -pitch : pitch;
  return out;
}

void VehicleForces::planarWheelAttitude(const mb::Data& d, int w, tyre::WheelKinematics& k) const {
  // The wheel rides on the base; in the linkage it turns with the body's
  // roll and pitch and, relative to the body, by the carrier's rotation over
  // its travel (bump and roll steer, camber gain).
  const PlanarLoads& P = *vehicle_.planar;
  const Mat3& Rs = d.R[vehicle_.layout.chassis];
  const Mat3 bodyTurn = Rs * P.sprungRest.transpose() * d.R[vehicle_.layout.base].transpose();
  const Vec3 travelTurn = Rs * (cornerTravel_[w] * P.turnPerTravel[w]);
  Vec3 axis = bodyTurn * k.spinAxis;
  axis += travelTurn.cross(axis);
  k.spinAxis = axis.normalized();
}

void VehicleForces::antiRollBars(mb::Data& d) {
  const int ch = vehicle_.layout.chassis;
  const Eigen::Vector3d up = d.R[ch].col(2);
  for (const AntiRollBarSpec& bar : vehicle_.spec.antiRollBars) {
    // A planar model's bar acts on the corners' deflection, suspension and
    // tyre in series (PlanarLoads::barRate), the others' on the suspension travel.
    const double f = vehicle_.planar ? vehicle_.planar->barRate[bar.left / 2] *
                                           (wheelCentreTravel(vehicle_, d, bar.left) - wheelCentreTravel(vehicle_, d, bar.right))
                                     : bar.rate * (suspensionTravel(vehicle_, d, bar.left) - suspensionTravel(vehicle_, d, bar.right));
    // + f: the left wheel pushed down (out of bump), the chassis up there; the right the other way.
    for (const auto& [w, sign] : {std::pair{bar.left, 1.0}, std::pair{bar.right, -1.0}}) {
      const int spindle = vehicle_.layout.wheels[w].spindle;
      const Eigen::Vector3d& centre = d.p[spindle];
      mb::addWorldForce(d, spindle, centre, -sign * f * up);
      mb::addWorldForce(d, ch, centre, sign * f * up);
      if (vehicle_.planar) outputs_[w].modelLoad += sign * f;  // the tyre carries what the bar puts on its corner
    }
  }
}

void VehicleForces::apply(const mb::Model&, mb::Data& d, double t) {
  const double h = std::max(0.0, t - state_->lastAccepted);
  if (vehicle_.planar) planarLoads(d);
  if (!vehicle_.spec.antiRollBars.empty()) antiRollBars(d);
  // Each wheel's kinematics and spin relative to its carrier, once per
  // evaluation (the brakes and the driveline both need the spin).
  std::array<tyre::WheelKinematics, 4> ks;
  std::array<double, 4> spins;
  for (int w = 0; w < 4; ++w) {
    const WheelLayout& wl = vehicle_.layout.wheels[w];
    ks[w] = wheelKinematics(d, w);
    if (vehicle_.planar) planarWheelAttitude(d, w, ks[w]);
    const tyre::WheelKinematics& k = ks[w];
    spins[w] = relativeSpin(d, w);
    const tyre::TyreOutput& out = evaluateTyre(w, k, h, modelLoad(w));
    if (out.inContact) mb::addWorldWrench(d, wl.spindle, out.point, out.force, out.moment);
    // Brakes react on the carrier (caliper on the upright): a joint torque.
    d.jointForce(wl.spinV) += wl.spinSign * brakeTorque(w, spins[w], h);
    if (!vehicle_.spec.powertrain) applyDriveTorque(d, w, k);
  }
  if (vehicle_.spec.powertrain) {
    powertrain(d, h, spins);
    for (int w : driven_) applyDriveTorque(d, w, ks[w]);
  }
  aerodynamics(d);
}

// The joint forces of wheel w's drive torque per N m, as applyDriveTorque
// applies it (times scale), added to out.
void VehicleForces::addDriveTorqueColumn(const mb::Model& model, const mb::Data& d, int w,
                                         const tyre::WheelKinematics& k, double scale,
                                         Eigen::Ref<Eigen::VectorXd> out) const {
  const WheelLayout& wl = vehicle_.layout.wheels[w];
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  switch (vehicle_.spec.driveReaction) {
    case DriveReaction::Carrier: out(wl.spinV) -= scale * wl.spinSign; break;
    case DriveReaction::Chassis:
      mb::addPathJointForces(model, d, vehicle_.layout.chassis,
                             mb::bodyWrench(d, vehicle_.layout.chassis, k.centre, zero, -k.spinAxis), -scale, out);
      [[fallthrough]];
    case DriveReaction::None:
      mb::addPathJointForces(model, d, wl.spindle, mb::bodyWrench(d, wl.spindle, k.centre, zero, k.spinAxis), -scale,
                             out);
      break;
  }
}

void VehicleForces::applyDriveTorque(mb::Data& d, int w, const tyre::WheelKinematics& k) const {
  const WheelContact& c = state_->wheels[w];
  if (c.driveTorque == 0.0) return;
  const WheelLayout& wl = vehicle_.layout.wheels[w];
  const Eigen::Vector3d torque = c.driveTorque * k.spinAxis;
  switch (vehicle_.spec.driveReaction) {
    case DriveReaction::Carrier: d.jointForce(wl.spinV) += wl.spinSign * c.driveTorque; break;
    case DriveReaction::Chassis:
      mb::addWorldWrench(d, wl.spindle, k.centre, Eigen::Vector3d::Zero(), torque);
      mb::addWorldWrench(d, vehicle_.layout.chassis, k.centre, Eigen::Vector3d::Zero(), -torque);
      break;
    case DriveReaction::None: mb::addWorldWrench(d, wl.spindle, k.centre, Eigen::Vector3d::Zero(), torque); break;
  }
}

double VehicleForces::engineSpeed(const mb::Data& d) const {
  // The crank's rate relative to the chassis, about the engine body's x axis.
  const int e = vehicle_.layout.engine;
  const int parent = vehicle_.model.bodies[e].parent;
  return (d.vel[e].tail<3>() - d.Xup[e].E * d.vel[parent].tail<3>()).x();
}

template <typename T>
T VehicleForces::drivenSpeed(const std::array<T, 4>& spins) const {
  T sum = T(0.0);
  for (int w : driven_) sum += spins[w];  // about the spindle's y: + rolls forwards on either side
  return driven_.empty() ? T(0.0) : T(sum / static_cast<double>(driven_.size()));
}

void VehicleForces::powertrain(mb::Data& d, double h, const std::array<double, 4>& spins) {
  d.jointForce(vehicle_.layout.engineV) += drivelineTorques(engineSpeed(d), spins, h);
}

template <typename S>
VehicleForces::DrivelineTorquesT<S> VehicleForces::drivelineAt(const S& engine, const std::array<S, 4>& spins,
                                                               double h) const {
  const PowertrainSpec& P = *vehicle_.spec.powertrain;
  const DrivelineState& s = state_->driveline;
  DrivelineTorquesT<S> T;
  T.output = drivenSpeed(spins);
  T.engine = engineTorque(P.engine, engine, s.command.throttle);
  // In neutral the clutch turns the gearbox's input shaft alone (its inertia is the engine's).
  T.clutch = s.command.ratio == 0.0 ? S(0.0)
                                    : clutchTorque(P.clutch, s.command.clutchCapacity, s.clutchDeflection,
                                                   S(engine - s.command.ratio * T.output), h);
  // The differential: an equal share of the gearbox output for each driven
  // wheel (the torque balance of an open differential), plus the viscous
  // coupling's torque from the faster wheels to the slower.
  const S share = s.command.ratio * T.clutch / static_cast<double>(driven_.size());
  for (int w : driven_) T.drive[w] = share - P.viscousCoupling * (spins[w] - T.output);
  return T;
}

double VehicleForces::drivelineTorques(double engine, const std::array<double, 4>& spins, double h) {
  const DrivelineTorques T = drivelineAt(engine, spins, h);
  DrivelineState& s = state_->driveline;
  s.engineSpeed = engine;
  s.outputSpeed = T.output;
  s.engineTorque = T.engine;
  s.clutchTorque = T.clutch;
  for (int w : driven_) state_->wheels[w].driveTorque = T.drive[w];
  return T.engine - T.clutch;
}

void VehicleForces::aerodynamics(mb::Data& d) const {
  const VehicleSpec& S = vehicle_.spec;
  if (S.dragArea <= 0 && S.liftAreaFront == 0 && S.liftAreaRear == 0) return;
  const int ch = vehicle_.layout.chassis;
  const Vec3& com = vehicle_.model.bodies[ch].com;
  const Eigen::Vector3d v = mb::pointVelocity(d, ch, com);
  if (S.dragArea > 0) mb::addWorldForce(d, ch, mb::pointPosition(d, ch, com), -S.dragArea * v.norm() * v);
  if (S.liftAreaFront == 0 && S.liftAreaRear == 0) return;
  // Lift on the air speed along the chassis' x, above the axles' wheel centres at the COM's height.
  const double u = d.R[ch].col(0).dot(v);
  const Eigen::Vector3d up = d.R[ch].col(2);
  for (int axle = 0; axle < 2; ++axle) {
    const double area = axle == 0 ? S.liftAreaFront : S.liftAreaRear;
    const Vec3 centre = 0.5 * (vehicle_.layout.wheelCentreAtDesign[2 * axle] + vehicle_.layout.wheelCentreAtDesign[2 * axle + 1]);
    const Vec3 at(centre.x(), com.y(), com.z());  // chassis frame
    mb::addWorldForce(d, ch, mb::pointPosition(d, ch, at), area * u * u * up);
  }
}

void VehicleForces::acceptStep(const mb::Model&, const mb::Data& d, double t, double hNext) {
  const double h = sinceAccepted(t);
  for (int w = 0; w < 4; ++w) acceptWheel(w, wheelKinematics(d, w), relativeSpin(d, w), h, hNext);
  if (vehicle_.spec.powertrain) {
    std::array<double, 4> spins;
    for (int w = 0; w < 4; ++w) spins[w] = relativeSpin(d, w);
    acceptDriveline(engineSpeed(d), spins, h);
  }
  markAccepted(t, hNext);
}

const tyre::TyreOutput& VehicleForces::evaluateTyre(int w, const tyre::WheelKinematics& k, double h,
                                                     std::optional<double> load) {
  const WheelContact& c = state_->wheels[w];
  WheelOutput& o = outputs_[w];
  o.spinRate = k.spinRate;
  tyres_[w].evaluate(k, groundAt(w, k.centre), c.slip, h, load, o.out);
  return o.out;
}

void VehicleForces::acceptWheel(int w, const tyre::WheelKinematics& k, double relativeSpin, double h, double hNext) {
  WheelContact& c = state_->wheels[w];
  // Transient slips matter only in the low-speed range (the last
  // evaluation's state says whether the wheel is in it).
  const tyre::TyreOutput& out = outputs_[w].out;  // the step's last evaluation
  if (out.slipState.active || !out.inContact)
    c.slip = tyres_[w].evaluate(k, groundAt(w, k.centre), c.slip, h, modelLoad(w)).slipState;
  else
    c.slip.active = false;
  c.acceptedForce = out.inContact ? out.force : Eigen::Vector3d::Zero();
  c.acceptedInContact = out.inContact;
  c.acceptedFx = out.Fx;
  c.acceptedFy = out.Fy;
  c.acceptedFz = out.Fz;
  // Ground under the wheel at the end of the next step.
  const Eigen::Vector3d travel = hNext * k.centreVelocity;
  prepareGround(w, k.centre + travel, k.spinAxis, travel);
  if (c.brakeCapacity > 0) {
    const double limit = c.brakeCapacity / kBrakeStiffness;
    c.brakeDeflection = std::clamp(c.brakeDeflection + h * relativeSpin, -limit, limit);
  } else {
    c.brakeDeflection = 0;
  }
}

void VehicleForces::acceptDriveline(double engine, const std::array<double, 4>& spins, double h) {
  DrivelineState& s = state_->driveline;
  s.clutchDeflection = s.command.ratio == 0.0
                           ? 0.0
                           : advanceClutchDeflection(vehicle_.spec.powertrain->clutch, s.command.clutchCapacity,
                                                     s.clutchDeflection, engine - s.command.ratio * drivenSpeed(spins), h);
}

void VehicleForces::markAccepted(double t, double hNext) {
  state_->lastAccepted = t;
  state_->planesReady = true;
  state_->planesFor = t + hNext;
}

#define BDFCAR_FORCE_LAWS(T)                                                                                     \
  template T VehicleForces::brakeTorque(int, const T&, double) const;                                            \
  template void VehicleForces::tyreForce(int, const tyre::WheelKinematicsT<T>&, double, std::optional<T>,        \
                                         tyre::TyreOutputT<T>&) const;                                           \
  template std::array<T, 4> VehicleForces::planarLoadShift(const tyre::Vec3T<T>&, const tyre::Vec3T<T>&) const; \
  template T VehicleForces::drivenSpeed(const std::array<T, 4>&) const;                                          \
  template VehicleForces::DrivelineTorquesT<T> VehicleForces::drivelineAt(const T&, const std::array<T, 4>&, double) const;
BDFCAR_FORCE_LAWS(double)
BDFCAR_FORCE_LAWS(ad::Dual)
#undef BDFCAR_FORCE_LAWS

}  // namespace bdfcar::vehicle
