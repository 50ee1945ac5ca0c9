#include "scenario/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <Eigen/Geometry>
#include <stdexcept>
#include <variant>

#include "multibody/kinematics.h"
#include "scenario/course_line.h"
#include "scenario/driver_identification.h"
#include "vehicle/derivation_cache.h"
#include "vehicle/motion_ratio.h"
#include "portable_math.h"

namespace bdfcar::scenario {

double RackSignal::steerAt(double t) const {
  return segment.scripted ? scripted_.at(t).value : segment.steer(t);
}

double RackSignal::rateAt(double t) const { return segment.scripted ? scripted_.at(t).rate : segment.rate(t); }

SignalValue RackSignal::at(double t) const {
  if (segment.scripted) {
    const SignalValue s = scripted_.at(t);
    return {gain_ * s.value, gain_ * s.rate, gain_ * s.accel};
  }
  return {gain_ * segment.steer(t), gain_ * segment.rate(t), gain_ * segment.a};
}

std::unique_ptr<Signal> makeSignal(const SignalSpec& s) {
  switch (s.kind) {
    case SignalSpec::Kind::None: return std::make_unique<ConstantSignal>(0.0);
    case SignalSpec::Kind::Constant: return std::make_unique<ConstantSignal>(s.level);
    case SignalSpec::Kind::Ramp: return std::make_unique<RampSignal>(s.start, s.duration, s.level);
    case SignalSpec::Kind::Sine: return std::make_unique<SinePeriodSignal>(s.start, s.duration, s.level, s.periods);
    case SignalSpec::Kind::SineWithDwell:
      return std::make_unique<SineWithDwellSignal>(s.start, s.duration, s.level, s.dwell);
    case SignalSpec::Kind::Chirp: return std::make_unique<ChirpSignal>(s.start, s.duration, s.level, s.f0, s.f1);
    case SignalSpec::Kind::Square: return std::make_unique<SquareSignal>(s.start, s.duration, s.level);
    case SignalSpec::Kind::Table: return std::make_unique<TableSignal>(s.times, s.values);
  }
  return std::make_unique<ConstantSignal>(0.0);
}


namespace {

// The most torque per driven wheel the car can put down: its [driveline]'s,
// or its engine's best in first gear; infinite on neither.
double driveLimit(const vehicle::Vehicle& v) {
  if (v.spec.powertrain) {
    const vehicle::PowertrainSpec& p = *v.spec.powertrain;
    int driven = 0;
    for (const vehicle::WheelSpec& w : v.spec.wheels) driven += w.driven ? 1 : 0;
    const double peak = *std::max_element(p.engine.torque.begin(), p.engine.torque.end());
    return peak * p.gearbox.overall(1) / std::max(1, driven);
  }
  return v.spec.maxDriveTorque > 0 ? v.spec.maxDriveTorque : std::numeric_limits<double>::infinity();
}

// The forward speed below which some tyre of the car blends in its transient
// (low-speed) slips (tyre/low_speed_slips.h).
double lowSpeedRange(const vehicle::VehicleSpec& v) {
  double range = 0;
  for (const vehicle::WheelSpec& w : v.wheels)
    range = std::max(range, std::visit([](const auto& p) { return p.lowSpeed.blend1; }, w.tyre));
  return range;
}

}  // namespace

namespace {
// The scripted steering; one that does not start at zero is ramped in during settling.
std::unique_ptr<Signal> steeringSignal(const ScenarioSpec& spec) {
  std::unique_ptr<Signal> s = makeSignal(spec.steering);
  if (spec.settleTime > 0 && s->at(0.0).value != 0.0)
    return std::make_unique<RampedInSignal>(std::move(s), -spec.settleTime);
  return s;
}
}  // namespace

CarSteering Simulation::carSteering() const {
  const vehicle::Vehicle& v = world_->linkageVehicle();
  return {v.spec.steering.steeringWheelFull, vehicle::roadWheelAnglePerSteer(v), v.spec.geometry.wheelbase};
}

Simulation::Simulation(const ScenarioSpec& spec) : Simulation(buildWorld(spec)) {}

Simulation::Simulation(std::shared_ptr<const World> world)
    : world_(std::move(world)),
      steering_(steeringSignal(world_->spec)),
      throttle_(makeSignal(world_->spec.throttle)),
      brake_(makeSignal(world_->spec.brake)),
      rack_(world_->vehicle.layout.rackAxisSign * -world_->vehicle.spec.steering.rackTravelFull, *steering_,
            state_.rack),
      steeringLimits_(steeringLimits(world_->vehicle.spec.steering)),
      startX_(world_->spec.startX),
      startY_(world_->spec.startY),
      startHeading_(world_->spec.startHeading) {
  const ScenarioSpec& spec = world_->spec;
  const vehicle::Vehicle& veh = world_->vehicle;
  rungs_.push_back(makeRung(veh));
  if (world_->planar) {
    rungs_.push_back(makeRung(*world_->planar));
    // Contact points relative to the centre of mass, from the planar model's load transfer.
    const vehicle::PlanarLoads& P = *world_->planar->planar;
    std::array<Eigen::Vector2d, 4> offsets;
    std::array<tyre::TyreParams, 4> tyres{veh.wheel(0).tyre, veh.wheel(1).tyre, veh.wheel(2).tyre, veh.wheel(3).tyre};
    for (int w = 0; w < 4; ++w) offsets[w] = (P.basePoint[w] - P.comInBase).head<2>();
    policy_.emplace(*world_->terrain, world_->planar->model.bodies[world_->planar->layout.base].inParent.origin.z(),
                    offsets, tyres, world_->planarLevel);
  }
  vehicle::ByteBuffer models;
  for (const Rung& r : rungs_) models.put(vehicle::derivationFingerprint(*r.vehicle));
  modelFingerprint_ = vehicle::hashBytes(models.bytes);
  state_.model = modelFingerprint_;
  activate(0);
  if (veh.spec.powertrain) transmission_.emplace(*veh.spec.powertrain, state_.transmission);
  if (spec.speedControl.enabled)
    speed_.emplace(spec.speedControl.profile, SpeedControllerGains{spec.speedControl.kp, spec.speedControl.ki},
                   state_.speedIntegral,
                   // The driveline's limit per driven wheel (none on a vehicle without one).
                   driveLimit(veh));
  if (spec.pathFollower.enabled) {
    PathFollowerParams p;
    p.lookAheadTime = spec.pathFollower.lookAheadTime;
    p.minLookAhead = spec.pathFollower.minLookAhead;
    p.wheelbase = veh.spec.geometry.wheelbase;
    // Steering ratio from the kinematics of the data.
    p.steerPerRoadWheel = 1.0 / std::max(1e-3, vehicle::roadWheelAnglePerSteer(world_->linkageVehicle()));
    const PathFollowerSpec& f = spec.pathFollower;
    PathTarget target;
    if (f.path == PathFollowerSpec::Path::Course) {
      // Keep 40 % of each lane's spare width for the tracking error; the course runs along +x.
      target = [c = *world_->course, w = vehicleWidth(veh)](double x, double, double yaw, double L) {
        const double tx = x + L * pm::cos(yaw);
        return Eigen::Vector2d(tx, c.drivingLineY(tx, w, 0.6));
      };
    } else if (f.path == PathFollowerSpec::Path::Polyline) {
      target = [path = PolylinePath(f.points, f.closed)](double x, double y, double, double L) {
        return path.target(x, y, L);
      };
    } else {
      // The circle through the start, its centre to the left (or right) of the start heading.
      const double side = f.direction;
      CirclePath c;
      c.radius = f.radius;
      c.direction = side;
      c.centre = Eigen::Vector2d(spec.startX, spec.startY) +
                 side * f.radius * Eigen::Vector2d(-pm::sin(spec.startHeading), pm::cos(spec.startHeading));
      target = [c](double x, double y, double, double L) { return c.target(x, y, L); };
    }
    if (f.law == PathFollowerSpec::Law::Preview) {
      PreviewDriverParams pp = previewDriverParams(world_->linkageVehicle(), startFriction(), spec.tick);
      pp.previewTime = f.previewTime;
      pp.car = identifySingleTrack(spec, world_->scene, pp.car).car;  // the car as it answers
      preview_.emplace(pp, pathOffset(veh));
    } else {
      follower_.emplace(p, target, state_.follower);
    }
  }
}

Simulation::~Simulation() = default;

double Simulation::startFriction() const {
  const terrain::Hit g = world_->terrain->castRay(Eigen::Vector3d(spec().startX, spec().startY, 1e3),
                                                  -Eigen::Vector3d::UnitZ(), 2e3);
  return g.hit ? g.friction : 1.0;
}

PathOffset Simulation::pathOffset(const vehicle::Vehicle& veh) const {
  const PathFollowerSpec& f = spec().pathFollower;
  if (f.path == PathFollowerSpec::Path::Course) {
    // The line through the course for this car's footprint, followed by the
    // chassis' centre of mass (the footprint's centre from it).
    const auto& g = veh.spec.geometry;
    const mb::Vec3 com = veh.model.bodies[veh.layout.chassis].com;
    const CourseLine line = computeCourseLine(*world_->course, g.length, vehicleWidth(veh),
                                              Eigen::Vector2d(g.bodyOffset.x() - com.x(), g.bodyOffset.y() - com.y()),
                                              f.lineMargin);
    return [line](double x, double y) { return y - line.y(x); };
  }
  if (f.path == PathFollowerSpec::Path::Polyline)
    return [path = PolylinePath(f.points, f.closed)](double x, double y) { return path.offset(x, y); };
  const double side = f.direction;
  const Eigen::Vector2d centre = Eigen::Vector2d(spec().startX, spec().startY) +
                                 side * f.radius * Eigen::Vector2d(-pm::sin(spec().startHeading), pm::cos(spec().startHeading));
  // + inside a left-hand circle (left of its direction), outside a right-hand one.
  return [centre, side, R = f.radius](double x, double y) { return side * (R - (Eigen::Vector2d(x, y) - centre).norm()); };
}

Simulation::StartPose Simulation::startPose() const {
  const Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();
  const Eigen::Matrix3d yaw = mb::rotZ(startHeading_);
  const Eigen::Vector3d start(startX_, startY_, 0.0);
  auto groundAt = [&](const Eigen::Vector3d& p, int w) {
    const terrain::Hit g = world_->terrain->castRay(Eigen::Vector3d(p.x(), p.y(), 1e3), down, 2e3);
    if (!g.hit) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "%s: no ground under wheel %s at the start (x = %.2f m, y = %.2f m): the start position "
                    "([start] position, heading) puts the car off the terrain",
                    spec().sourceFile.c_str(), vehicle::kCornerNames[w], p.x(), p.y());
      throw PrepareError(text);
    }
    return g.point.z();
  };
  // Least-squares plane z = c0 + c1 x + c2 y through the ground under the wheels.
  Eigen::Matrix<double, 4, 3> A;
  Eigen::Vector4d b;
  for (int w = 0; w < 4; ++w) {
    const mb::Vec3 centre = vehicle().spec.bodies[vehicle().layout.wheels[w].spindle].com;
    const Eigen::Vector3d p = start + yaw * Eigen::Vector3d(centre.x(), centre.y(), 0.0);
    A.row(w) << 1.0, p.x(), p.y();
    b(w) = groundAt(p, w);
  }
  const Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
  // The car starts on the plane through the ground under its wheels: a wall
  // or a step under it is no such plane.
  const Eigen::Vector4d off = A * c - b;
  int worst = 0;
  off.cwiseAbs().maxCoeff(&worst);
  if (std::abs(off(worst)) > kStartGroundStep) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "%s: the ground under wheel %s at the start is %.2f m %s the plane through the ground under the "
                  "four wheels (at most %.2f m): the car would start against a wall or over a step; move the start",
                  spec().sourceFile.c_str(), vehicle::kCornerNames[worst], std::abs(off(worst)),
                  off(worst) > 0 ? "below" : "above", kStartGroundStep);
    throw PrepareError(text);
  }
  Eigen::Vector3d n(-c(1), -c(2), 1.0);
  n.normalize();
  const Eigen::Vector3d heading = yaw.col(0);
  const Eigen::Vector3d x = (heading - heading.dot(n) * n).normalized();
  StartPose pose;
  pose.rotation.col(0) = x;
  pose.rotation.col(1) = n.cross(x);
  pose.rotation.col(2) = n;
  pose.groundZ = c(0) + c(1) * start.x() + c(2) * start.y();
  pose.origin = Eigen::Vector3d(start.x(), start.y(), pose.groundZ) + vehicle().spec.designHeight * n;
  return pose;
}

vehicle::EquilibriumReport Simulation::prepare(const std::atomic<bool>* stop) {
  // Settling on the full model; `auto` chooses from the first tick on.
  activate(0);
  state_.fidelity = {};
  const mb::Model& m = vehicle().model;
  const mb::Body& ch = m.bodies[vehicle().layout.chassis];
  const double t0 = -spec().settleTime;
  // Start pose: the design configuration placed on the ground at the start
  // point, its chassis aligned with the plane through the ground under the
  // four wheels (on a slope the car starts on the slope, not in it).
  integ::Vec q = vehicle::designPositions(vehicle());
  const StartPose pose = startPose();
  const double groundZ = pose.groundZ;
  const mb::Body& base = m.bodies[vehicle().layout.base];
  if (base.joint == mb::JointType::Planar) {
    // Level ground only: the planar model has no heave, roll or pitch of its base.
    const double slope = pm::acos(std::clamp(pose.rotation(2, 2), -1.0, 1.0));
    if (slope > 1e-3)
      throw PrepareError(spec().sourceFile + ": the ground under the start slopes by " +
                         std::to_string(slope * 180 / M_PI) +
                         " deg; [fidelity] suspension = planar needs level ground (use kinematic or linkage)");
    q(base.qIndex) = startX_;
    q(base.qIndex + 1) = startY_;
    q(base.qIndex + 2) = startHeading_;
  } else {
    q.segment<3>(ch.qIndex) = pose.origin;
    const Eigen::Quaterniond yaw(pose.rotation);
    q(ch.qIndex + 3) = yaw.w();
    q(ch.qIndex + 4) = yaw.x();
    q(ch.qIndex + 5) = yaw.y();
    q(ch.qIndex + 6) = yaw.z();
  }
  std::string msg;
  const integ::Vec design = q;
  if (!vehicle::assemble(vehicle(), *dae_, t0, q, msg))
    throw PrepareError(spec().vehicleFile + ": the vehicle cannot be assembled at the start: " + msg);
  if (const auto far = vehicle::farFromDesign(vehicle(), design, q)) throw PrepareError(*far);
  integ::Vec lambda = integ::Vec::Zero(m.nc);
  vehicle::EquilibriumReport eq = vehicle::settleStatic(vehicle(), *dae_, *forces_, t0, q, lambda);
  if (!eq.converged)
    throw PrepareError(spec().vehicleFile + ": no static equilibrium at the start: " + eq.message);
  eq.chassisHeight -= groundZ;
  eq.comHeight -= groundZ;

  // Initial speed: every body moves with the chassis; wheels roll at their loaded radius.
  integ::Vec v = integ::Vec::Zero(m.nv);
  mb::Data& d = dae_->data();
  mb::updatePositions(m, q, d);
  if (base.joint == mb::JointType::Planar) {
    v(base.vIndex) = spec().initialSpeed;
  } else {
    const Eigen::Vector3d worldVel = spec().initialSpeed * (d.R[vehicle().layout.chassis] * Eigen::Vector3d::UnitX());
    v.segment<3>(ch.vIndex) = d.R[vehicle().layout.chassis].transpose() * worldVel;
  }
  for (int w = 0; w < 4; ++w) {
    const vehicle::WheelLayout& wl = vehicle().layout.wheels[w];
    const double rolling = tyre::unloadedRadius(vehicle().wheel(w).tyre) - forces_->outputs()[w].out.deflection;
    v(wl.spinV) = wl.spinSign * spec().initialSpeed / rolling;
  }
  if (transmission_) {
    // In the gear that suits the speed, the engine at the speed it gives (idling at rest).
    const DrivelineSpeeds s = drivelineSpeeds(v, spec().initialSpeed, true);
    transmission_->start(s.output, s.vx);
    const double locked = vehicle().spec.powertrain->gearbox.overall(transmission_->state().gear) * s.output;
    v(vehicle().layout.engineV) = transmission_->state().engagement >= 1.0
                                      ? locked
                                      : std::max(locked, vehicle().spec.powertrain->engine.idleSpeed);
  }
  forces_->reset(t0);
  integ::Message im;
  integ::Vec qs, vs;  // in the stepping model's coordinates
  fromMultibody(state_.rung, q, v, qs, vs);
  if (integrator_->initialize(t0, qs, vs, im) != integ::EvalStatus::Ok)
    throw std::runtime_error(std::string("initial state: ") + im.c_str());
  prepared_ = true;
  state_.airborne = 0;
  state_.scriptedDriver = true;
  rack_.segment = RackSegment{};
  // Settling: straight running with the scripted driver (steering is zero before tau = 0).
  const double h = spec().integrator.step;
  const long settleSteps = std::lround(spec().settleTime / h);
  for (long i = 0; i < settleSteps; ++i) {
    if (stop && stop->load()) {
      prepared_ = false;
      throw PrepareInterrupted("stopped while settling, at t = " + std::to_string(time()) + " s of " +
                               std::to_string(t0) + " s to 0");
    }
    const integ::StepReport r = step();
    if (!r.ok())
      throw std::runtime_error("diverged while settling at t = " + std::to_string(time()) + " s: " + r.message.c_str());
  }
  return eq;
}

integ::StepReport Simulation::step() {
  if (!prepared_) throw std::logic_error("Simulation::prepare() must run before step()");
  const double t = time(), h = spec().integrator.step;
  if (state_.scriptedDriver) {
    state_.input.throttle = throttle_->at(t).value;
    state_.input.brake = brake_->at(t).value;
    if (rack_.segment.scripted) state_.input.steer = steering_->at(t + h).value;
  }
  const double speed = forwardSpeed();
  applyDrive(state_.input, speed, h);
  state_.input.shift = 0;  // a gear request acts once, at the tick's first step
  // Newton's early end (FidelitySpec) above the tyres' low-speed range only:
  // below it their transient slips make each contact a stiff, lightly damped
  // spring, on which the sub-tolerance error one iteration leaves would keep
  // a stopped car trembling (at micrometres a second) instead of settling.
  const bool lowSpeed = std::abs(speed) < lowSpeedRange(vehicle().spec);
  integrator_->setNewtonEarlyEnd(spec().fidelity.stopWithinTolerance && !lowSpeed);
  integrator_->setLowSpeed(lowSpeed);
  integ::StepReport r = integrator_->step(h);
  if (!r.ok()) return r;
  bool grounded = false;
  for (const vehicle::WheelContact& w : forces_->wheels()) grounded = grounded || w.plane.valid;
  state_.airborne = grounded ? 0.0 : state_.airborne + h;
  if (vehicle().planar) {
    if (const std::optional<std::string> off = offLevelGround()) {
      if (policy_) {
        // `auto`'s scan missed it: the full model from here on.
        FidelityPolicy::forceFull(state_.fidelity);
        switchRung(0);
        return r;
      }
      r.status = integ::StepStatus::StateCheckFailed;
      r.message.set("%s", off->c_str());
      return r;
    }
  }
  if (const std::optional<std::string> over = overturned()) {
    r.status = integ::StepStatus::StateCheckFailed;
    r.message.set("%s", over->c_str());
    return r;
  }
  if (const std::optional<std::string> under = belowGround()) {
    r.status = integ::StepStatus::StateCheckFailed;
    r.message.set("%s", under->c_str());
    return r;
  }
  if (state_.airborne > kMaxAirborne) {
    const Eigen::Vector3d com = chassisState().com;
    r.status = integ::StepStatus::StateCheckFailed;
    r.message.set("the car left the terrain: no ground under any wheel for %.1f s (centre of mass at x = %.1f m, "
                  "y = %.1f m, z = %.1f m, t = %.2f s)",
                  kMaxAirborne, com.x(), com.y(), com.z(), time());
  }
  return r;
}

std::optional<std::string> Simulation::overturned() const {
  // The chassis' up axis pointing below the horizon: the car is on its
  // roof or side past 90 deg (a planar model cannot roll over).
  if (vehicle().planar) return std::nullopt;
  const mb::Body& ch = vehicle().model.bodies[vehicle().layout.chassis];
  const double* qc = integrator_->current().q.data() + (car_ ? 0 : ch.qIndex);  // a closed form holds it first
  // The z component of the chassis' z axis, from its quaternion (w, x, y, z):
  // no rotation matrix on the step while the car is upright.
  const double w = qc[3], x = qc[4], y = qc[5], z = qc[6];
  if (w * w - x * x - y * y + z * z >= 0) return std::nullopt;
  const Eigen::Matrix3d R = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  char buf[200];
  std::snprintf(buf, sizeof buf, "the car overturned at t = %.2f s (roll %.0f deg, pitch %.0f deg; x = %.1f m, y = %.1f m)",
                time(), pm::atan2(R(2, 1), R(2, 2)) * 180 / M_PI, -pm::asin(std::clamp(R(2, 0), -1.0, 1.0)) * 180 / M_PI,
                qc[0], qc[1]);
  return std::string(buf);
}

std::optional<std::string> Simulation::belowGround() const {
  // A wheel centre behind its contact plane has sunk through the road; one
  // whose ray found no ground (the ray starts a radius above the centre) may
  // be deep inside it: a ray from far above to the centre tells. The
  // chassis is looked at only when a wheel is off the ground.
  // The wheel centres of the last residual evaluation (the closed form's
  // own, or the multibody model's), the chassis frame at the accepted state.
  const mb::Data& d = dae_->data();
  const auto centre = [&](int w) -> const Eigen::Vector3d& {
    return car_ ? car_->wheelCentre(w) : d.p[vehicle().layout.wheels[w].spindle];
  };
  const auto groundAbove = [&](const Eigen::Vector3d& p) {
    constexpr double kAbove = 20.0;  // m
    return world_->terrain->castRay(p + kAbove * Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(), kAbove).hit;
  };
  char buf[300];
  bool lifted = false;
  for (int w = 0; w < 4; ++w) {
    const Eigen::Vector3d& c = centre(w);
    const vehicle::WheelContact& wc = forces_->wheels()[w];
    const bool sunk = wc.plane.valid ? (c - wc.plane.point).dot(wc.plane.normal) < 0 : groundAbove(c);
    lifted = lifted || !wc.plane.valid || !wc.acceptedInContact;
    if (!sunk) continue;
    std::snprintf(buf, sizeof buf,
                  "wheel %s's centre went below the ground at t = %.2f s (x = %.1f m, y = %.1f m, z = %.2f m, %s model)",
                  vehicle::kCornerNames[w], time(), c.x(), c.y(), c.z(), vehicle::fidelityName(vehicle().fidelity));
    return std::string(buf);
  }
  if (!lifted) return std::nullopt;
  const Eigen::Vector3d com = car_ ? car_->chassisOrigin(integrator_->current().q) : d.p[vehicle().layout.chassis];  // its reference frame's origin
  if (!groundAbove(com)) return std::nullopt;
  std::snprintf(buf, sizeof buf, "the chassis went below the ground at t = %.2f s (x = %.1f m, y = %.1f m, z = %.2f m, %s model)",
                time(), com.x(), com.y(), com.z(), vehicle::fidelityName(vehicle().fidelity));
  return std::string(buf);
}

std::optional<std::string> Simulation::offLevelGround() const {
  // The planar model has no heave, roll or pitch of its base: the ground
  // under every wheel must be its road plane, or the run stops saying so.
  const double road = vehicle().model.bodies[vehicle().layout.base].inParent.origin.z();
  const double level = FidelityPolicy::roadNormalZ();
  const auto& wheels = forces_->wheels();
  for (int w = 0; w < 4; ++w) {
    const tyre::ContactPlane& g = wheels[w].plane;
    const double rise = g.valid ? g.point.z() - road : NAN;
    if (g.valid && std::abs(rise) <= FidelityPolicy::kRoadHeight && g.normal.z() >= level) continue;
    const double grade = g.valid ? pm::hypot(g.normal.x(), g.normal.y()) / std::max(1e-9, g.normal.z()) : 0.0;
    char buf[700];
    std::snprintf(buf, sizeof buf,
                  "the planar model left level ground at t = %.2f s: under wheel %s at x = %.1f m, y = %.1f m the "
                  "ground %s (its slope there %.1f %%, %.1f deg; the road plane's height %.3f m, the ground's %.3f m); "
                  "[fidelity] suspension = planar drives on level ground only (use kinematic or linkage)",
                  time(), vehicle::kCornerNames[w], g.point.x(), g.point.y(),
                  !g.valid ? "is missing"
                           : (std::abs(rise) > FidelityPolicy::kRoadHeight ? (rise > 0 ? "rises above the road plane" : "drops below the road plane")
                                                                 : "slopes"),
                  100 * grade, pm::atan(grade) * 180 / M_PI, road, g.valid ? g.point.z() : NAN);
    return std::string(buf);
  }
  return std::nullopt;
}

RunState Simulation::save() {
  // Every model's Jacobian (a model switched back to keeps its own): a run
  // restored to this state finds none either.
  for (Rung& r : rungs_) r.integrator->markJacobianStale();
  return state_;
}

void Simulation::restore(const RunState& s) {
  for (Rung& r : rungs_) r.integrator->markJacobianStale();
  state_ = s;
  activate(state_.rung);
  prepared_ = true;
}

Simulation::ConstraintViolation Simulation::constraintViolation() {
  const integ::SolutionPoint& p = integrator_->current();
  integ::Residual r;
  r.resize(stepping_->sizes());
  integ::Message msg;
  // The evaluation leaves its outputs in the force laws' state: put it back,
  // so that looking does not change the run.
  const vehicle::VehicleForces::State keep = forces_->state();
  const integ::EvalStatus st = stepping_->residual(p.t, p.q, p.v, p.a, p.lambda, r, true, msg);
  forces_->setState(keep);
  if (st != integ::EvalStatus::Ok) return {INFINITY, INFINITY, INFINITY};
  auto maxAbs = [](const integ::Vec& x) { return x.size() ? x.cwiseAbs().maxCoeff() : 0.0; };
  return {maxAbs(r.phi), maxAbs(r.phiDot), maxAbs(r.phiDDot)};
}

vehicle::VehicleSample Simulation::sample() {
  if (!car_) return vehicle::sampleVehicle(vehicle(), *dae_, *forces_, integrator_->current());
  return vehicle::sampleVehicle(vehicle(), *dae_, *forces_, multibodyPoint(), true);  // evaluated there
}

vehicle::VehicleView Simulation::view() { return vehicle::viewVehicle(vehicle(), *dae_, *forces_, time()); }

}  // namespace bdfcar::scenario
