#include "scenario/simulation.h"

#include <algorithm>
#include <cmath>
#include <Eigen/QR>
#include <stdexcept>

#include "integrator/bdf.h"
#include "integrator/explicit.h"
#include "multibody/kinematics.h"
#include "terrain/bullet/bullet_terrain.h"
#include "terrain/terrain_file.h"
#include "vehicle/motion_ratio.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar::scenario {

void RackSignal::setSegment(double t0, double s0, double t1, double s1) {
  scripted_ = nullptr;
  t0_ = t0;
  s0_ = s0;
  t1_ = t1;
  s1_ = s1;
}

double RackSignal::steerAt(double t) const {
  if (scripted_) return scripted_->at(t).value;
  if (t >= t1_ || t1_ <= t0_) return s1_;
  if (t <= t0_) return s0_;
  return s0_ + (s1_ - s0_) * (t - t0_) / (t1_ - t0_);
}

mb::DriverTarget RackSignal::at(double t) const {
  if (scripted_) {
    const SignalValue s = scripted_->at(t);
    return {gain_ * s.value, gain_ * s.rate, gain_ * s.accel};
  }
  const double rate = (t1_ > t0_ && t < t1_ + 1e-12) ? (s1_ - s0_) / (t1_ - t0_) : 0.0;
  return {gain_ * steerAt(t), gain_ * rate, 0.0};
}

std::unique_ptr<Signal> makeSignal(const SignalSpec& s) {
  switch (s.kind) {
    case SignalSpec::Kind::None: return std::make_unique<ConstantSignal>(0.0);
    case SignalSpec::Kind::Constant: return std::make_unique<ConstantSignal>(s.level);
    case SignalSpec::Kind::Ramp: return std::make_unique<RampSignal>(s.start, s.duration, s.level);
    case SignalSpec::Kind::Sine: return std::make_unique<SinePeriodSignal>(s.start, s.duration, s.level);
    case SignalSpec::Kind::Table: return std::make_unique<TableSignal>(s.times, s.values);
  }
  return std::make_unique<ConstantSignal>(0.0);
}

double vehicleWidth(const vehicle::Vehicle& v) {
  const auto& g = v.spec.geometry;
  return std::max(g.trackFront, g.trackRear) + g.wheelWidth;
}

namespace {

std::unique_ptr<terrain::Terrain> loadGround(const ScenarioSpec& spec) {
  if (spec.terrainFile.empty()) return std::make_unique<terrain::PlaneTerrain>();
  return terrain::makeTerrain(terrain::loadTerrain(spec.terrainFile));
}

}  // namespace

Simulation::Simulation(const ScenarioSpec& spec)
    : spec_(spec),
      vehicle_(vehicle::buildVehicle(vehicle::loadVehicleFile(spec.vehicleFile))),
      terrain_(loadGround(spec)),
      rack_(vehicle_.layout.rackAxisSign * -vehicle_.spec.steering.rackTravelFull) {
  vehicle::TerrainContactOptions contact;
  contact.raysPerWheel = spec_.raysPerWheel;
  forces_ = std::make_unique<vehicle::VehicleForces>(vehicle_, *terrain_, contact);
  dae_ = std::make_unique<mb::MultibodyDae>(vehicle_.model);
  dae_->addForceProvider(forces_.get());
  dae_->setDriverSignal(vehicle_.layout.rackDriverSlot, &rack_);
  steering_ = makeSignal(spec_.steering);
  throttle_ = makeSignal(spec_.throttle);
  brake_ = makeSignal(spec_.brake);
  rack_.setScripted(steering_.get());
  if (spec_.speedControl.enabled)
    speed_.emplace(spec_.speedControl.target, SpeedControllerGains{spec_.speedControl.kp, spec_.speedControl.ki});
  if (spec_.course.iso3888) course_ = makeIso3888Course(vehicleWidth(vehicle_), spec_.course.startX, spec_.startY);
  if (spec_.pathFollower.enabled) {
    PathFollowerParams p;
    p.lookAheadTime = spec_.pathFollower.lookAheadTime;
    p.minLookAhead = spec_.pathFollower.minLookAhead;
    p.wheelbase = vehicle_.spec.geometry.wheelbase;
    // Steering ratio from the kinematics of the data.
    p.steerPerRoadWheel = 1.0 / std::max(1e-3, vehicle::roadWheelAnglePerSteer(vehicle_));
    // Keep 40 % of each lane's spare width for the tracking error.
    follower_.emplace(p, [c = *course_, w = vehicleWidth(vehicle_)](double x) { return c.drivingLineY(x, w, 0.6); });
  }
  makeIntegrator();
}

Simulation::~Simulation() = default;

void Simulation::makeIntegrator() {
  const IntegratorSpec& is = spec_.integrator;
  if (is.method == IntegratorMethod::Bdf) {
    integ::BdfOptions o;
    o.order = is.order;
    o.newtonIterations = is.newtonIterations;
    o.jacobianEvery = is.jacobianEvery;
    o.refreshWhenNotContracting = is.refreshWhenNotContracting;
    o.atol = is.atol;
    o.rtol = is.rtol;
    integrator_ = std::make_unique<integ::BdfIntegrator>(*dae_, o);
  } else {
    integ::ExplicitOptions o;
    o.method = is.method == IntegratorMethod::Rk4 ? integ::ExplicitMethod::RK4 : integ::ExplicitMethod::SemiImplicitEuler;
    integrator_ = std::make_unique<integ::ExplicitIntegrator>(*dae_, o);
  }
}

Simulation::StartPose Simulation::startPose() const {
  const Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(spec_.startHeading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d start(spec_.startX, spec_.startY, 0.0);
  auto groundAt = [&](const Eigen::Vector3d& p) {
    const terrain::Hit g = terrain_->castRay(Eigen::Vector3d(p.x(), p.y(), 1e3), down, 2e3);
    return g.hit ? g.point.z() : 0.0;
  };
  // Least-squares plane z = c0 + c1 x + c2 y through the ground under the wheels.
  Eigen::Matrix<double, 4, 3> A;
  Eigen::Vector4d b;
  for (int w = 0; w < 4; ++w) {
    const mb::Vec3 centre = vehicle_.spec.bodies[vehicle_.layout.wheels[w].spindle].com;
    const Eigen::Vector3d p = start + yaw * Eigen::Vector3d(centre.x(), centre.y(), 0.0);
    A.row(w) << 1.0, p.x(), p.y();
    b(w) = groundAt(p);
  }
  const Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
  Eigen::Vector3d n(-c(1), -c(2), 1.0);
  n.normalize();
  const Eigen::Vector3d heading = yaw.col(0);
  const Eigen::Vector3d x = (heading - heading.dot(n) * n).normalized();
  StartPose pose;
  pose.rotation.col(0) = x;
  pose.rotation.col(1) = n.cross(x);
  pose.rotation.col(2) = n;
  pose.groundZ = c(0) + c(1) * start.x() + c(2) * start.y();
  pose.origin = Eigen::Vector3d(start.x(), start.y(), pose.groundZ) + vehicle_.spec.designHeight * n;
  return pose;
}

vehicle::EquilibriumReport Simulation::prepare() {
  const mb::Model& m = vehicle_.model;
  const mb::Body& ch = m.bodies[vehicle_.layout.chassis];
  const double t0 = -spec_.settleTime;
  // Start pose: the design configuration placed on the ground at the start
  // point, its chassis aligned with the plane through the ground under the
  // four wheels (on a slope the car starts on the slope, not in it).
  integ::Vec q = vehicle::designPositions(vehicle_);
  const StartPose pose = startPose();
  const double groundZ = pose.groundZ;
  q.segment<3>(ch.qIndex) = pose.origin;
  const Eigen::Quaterniond yaw(pose.rotation);
  q(ch.qIndex + 3) = yaw.w();
  q(ch.qIndex + 4) = yaw.x();
  q(ch.qIndex + 5) = yaw.y();
  q(ch.qIndex + 6) = yaw.z();
  std::string msg;
  if (!vehicle::assemble(vehicle_, *dae_, t0, q, msg)) throw std::runtime_error(spec_.vehicleFile + ": " + msg);
  integ::Vec lambda = integ::Vec::Zero(m.nc);
  vehicle::EquilibriumReport eq = vehicle::settleStatic(vehicle_, *dae_, *forces_, t0, q, lambda);
  if (!eq.converged) throw std::runtime_error(spec_.vehicleFile + ": " + eq.message);
  eq.chassisHeight -= groundZ;
  eq.comHeight -= groundZ;

  // Initial speed: every body moves with the chassis; wheels roll at their loaded radius.
  integ::Vec v = integ::Vec::Zero(m.nv);
  mb::Data& d = dae_->data();
  mb::updatePositions(m, q, d);
  const Eigen::Vector3d worldVel = spec_.initialSpeed * (d.R[vehicle_.layout.chassis] * Eigen::Vector3d::UnitX());
  v.segment<3>(ch.vIndex) = d.R[vehicle_.layout.chassis].transpose() * worldVel;
  for (int w = 0; w < 4; ++w) {
    const vehicle::WheelLayout& wl = vehicle_.layout.wheels[w];
    const double rolling = wl.spec->tyre.unloadedRadius - forces_->wheels()[w].out.deflection;
    v(wl.spinV) = wl.spinSign * spec_.initialSpeed / rolling;
  }
  forces_->reset(t0);
  integ::Message im;
  if (integrator_->initialize(t0, q, v, im) != integ::EvalStatus::Ok)
    throw std::runtime_error(std::string("initial state: ") + im.c_str());
  prepared_ = true;
  airborne_ = 0;
  // Settling: straight running with the scripted driver (steering is zero before tau = 0).
  const double h = spec_.integrator.step;
  const long settleSteps = std::lround(spec_.settleTime / h);
  for (long i = 0; i < settleSteps; ++i) {
    const integ::StepReport r = step();
    if (!r.ok())
      throw std::runtime_error("diverged while settling at t = " + std::to_string(time()) + " s: " + r.message.c_str());
  }
  return eq;
}

void Simulation::applyDrive(const DriverInput& in, double vx, double h) {
  double pi = 0;
  if (speed_) pi = speed_->torque(vx, h);
  for (int w = 0; w < 4; ++w) {
    const vehicle::WheelSpec& ws = *vehicle_.layout.wheels[w].spec;
    const double drive = ws.driven ? in.throttle * vehicle_.spec.maxDriveTorque + pi : 0.0;
    forces_->setDriveTorque(w, drive);
    forces_->setBrakeCapacity(w, in.brake * ws.brakeTorque);
  }
}

integ::StepReport Simulation::advance(const DriverInput& in) {
  if (!prepared_) throw std::logic_error("Simulation::prepare() must run before step()");
  lastInput_ = in;
  const double h = spec_.integrator.step;
  integ::StepReport r = integrator_->step(h);
  if (!r.ok()) return r;
  bool grounded = false;
  for (const vehicle::WheelContact& w : forces_->wheels()) grounded = grounded || w.plane.valid;
  airborne_ = grounded ? 0.0 : airborne_ + h;
  if (airborne_ > kMaxAirborne) {
    const Eigen::Vector3d com = chassisState().com;
    r.status = integ::StepStatus::StateCheckFailed;
    r.message.set("the car left the terrain: no ground under any wheel for %.1f s (centre of mass at x = %.1f m, "
                  "y = %.1f m, z = %.1f m, t = %.2f s)",
                  kMaxAirborne, com.x(), com.y(), com.z(), time());
  }
  return r;
}

Simulation::ChassisState Simulation::chassisState() const {
  // From the coordinates directly (no kinematic pass): the free joint holds
  // the chassis position and attitude, its velocity is in chassis axes.
  const integ::SolutionPoint& p = integrator_->current();
  const mb::Body& ch = vehicle_.model.bodies[vehicle_.layout.chassis];
  const double* qc = p.q.data() + ch.qIndex;
  const Eigen::Matrix3d R = Eigen::Quaterniond(qc[3], qc[4], qc[5], qc[6]).toRotationMatrix();
  const Eigen::Vector3d vb = p.v.segment<3>(ch.vIndex), wb = p.v.segment<3>(ch.vIndex + 3);
  ChassisState s;
  s.com = Eigen::Vector3d(qc[0], qc[1], qc[2]) + R * ch.com;
  s.yaw = std::atan2(R(1, 0), R(0, 0));
  s.vx = (vb + wb.cross(ch.com)).x();
  s.yawRate = wb.z();
  return s;
}

integ::StepReport Simulation::step() {
  const double t = time(), h = spec_.integrator.step;
  const ChassisState s = chassisState();
  DriverInput in;
  in.throttle = throttle_->at(t).value;
  in.brake = brake_->at(t).value;
  if (follower_ && t >= 0) {
    in.steer = follower_->steer(s.com.x(), s.com.y(), s.yaw, s.vx, s.yawRate, h);
    rack_.setSegment(t, rack_.steerAt(t), t + h, in.steer);
  } else {
    in.steer = steering_->at(t + h).value;
  }
  applyDrive(in, s.vx, h);
  return advance(in);
}

integ::StepReport Simulation::step(const DriverInput& input) {
  const double t = time(), h = spec_.integrator.step;
  DriverInput in = input;
  in.steer = std::clamp(in.steer, -1.0, 1.0);
  in.throttle = std::clamp(in.throttle, 0.0, 1.0);
  in.brake = std::clamp(in.brake, 0.0, 1.0);
  rack_.setSegment(t, rack_.steerAt(t), t + h, in.steer);
  applyDrive(in, chassisState().vx, h);
  return advance(in);
}

vehicle::VehicleSample Simulation::sample() { return vehicle::sampleVehicle(vehicle_, *dae_, *forces_, integrator_->current()); }

vehicle::VehicleView Simulation::view() { return vehicle::viewVehicle(vehicle_, *dae_, *forces_, time()); }

}  // namespace bdfcar::scenario
