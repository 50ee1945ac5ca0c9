// The driver's side of a Simulation: a tick's input (the scenario's
// scripted driver, the path follower and speed hold, or a person's), the
// steering system to the rack, the drive and brake torques, and a
// powertrain car's pedals, gears and clutch.
#include "scenario/simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "portable_math.h"

namespace bdfcar::scenario {

DrivelineSpeeds Simulation::drivelineSpeeds(const integ::Vec& v, double vx, bool multibody) const {
  // A closed form holds the spins and the crank at its own places.
  const bool closed = car_ && !multibody;
  DrivelineSpeeds s;
  s.vx = vx;
  s.engine = v(closed ? car_->engineV() : vehicle().layout.engineV);
  int n = 0;
  for (int w = 0; w < 4; ++w)
    if (vehicle().wheel(w).driven) {
      s.output += vehicle().layout.wheels[w].spinSign * v(closed ? car_->spinV(w) : vehicle().layout.wheels[w].spinV);
      ++n;
    }
  s.output /= std::max(1, n);
  return s;
}

void Simulation::applyPowertrain(DriverInput in, double vx, double h) {
  const vehicle::PowertrainSpec& p = *vehicle().spec.powertrain;
  const DrivelineSpeeds s = drivelineSpeeds(integrator_->current().v, vx);
  if (speed_ && speed_->active(time())) {
    // The speed hold works the pedals: its torque per driven wheel as a
    // share of what the engine gives in this gear now, or as a brake.
    const double T = speed_->torque(vx, h, time());
    const double ratio = std::abs(p.gearbox.overall(transmission_->state().gear));
    int driven = 0;
    double brakes = 0;
    for (int w = 0; w < 4; ++w) {
      driven += vehicle().wheel(w).driven ? 1 : 0;
      brakes += vehicle().wheel(w).brakeTorque;
    }
    const double available = vehicle::fullLoadTorque(p.engine, s.engine) * ratio / std::max(1, driven);
    in.throttle = T > 0 ? (available > 0 ? std::min(1.0, T / available) : 1.0) : 0.0;
    in.brake = T < 0 && brakes > 0 ? std::min(1.0, -T * driven / brakes) : in.brake;
  } else if (speed_) {
    speed_->torque(vx, h, time());  // keeps its phase (its integral starts afresh when it takes over)
  }
  forces_->setDriveline(transmission_->update(in, s, h));
  for (int w = 0; w < 4; ++w) {
    const vehicle::WheelSpec& ws = vehicle().wheel(w);
    forces_->setDriveTorque(w, 0.0);
    const double handbrake = w >= 2 ? in.handbrake * p.handbrakeTorque : 0.0;
    forces_->setBrakeCapacity(w, std::max(in.brake * ws.brakeTorque, handbrake));
  }
}

PowertrainChannels Simulation::powertrainChannels() const {
  PowertrainChannels c;
  if (!transmission_) return c;
  // From the accepted state and the command held over its step (not the
  // force law's latest evaluation, which a sample or a view may have made).
  const vehicle::PowertrainSpec& p = *vehicle().spec.powertrain;
  const vehicle::DrivelineState& d = forces_->driveline();
  const DrivelineSpeeds s = drivelineSpeeds(integrator_->current().v, 0.0);
  const double rpm = 60.0 / (2.0 * M_PI), slip = s.engine - d.command.ratio * s.output;
  c.engineRpm = s.engine * rpm;
  c.gear = transmission_->state().gear;
  c.clutch = transmission_->state().engagement;
  c.clutchSlipRpm = slip * rpm;
  c.engineTorque = vehicle::engineTorque(p.engine, s.engine, d.command.throttle);
  c.clutchTorque = d.command.ratio == 0.0
                       ? 0.0
                       : vehicle::clutchTorque(p.clutch, d.command.clutchCapacity, d.clutchDeflection, slip, 0.0);
  c.throttle = d.command.throttle;
  c.handbrake = state_.input.handbrake;
  return c;
}

void Simulation::applyDrive(const DriverInput& in, double vx, double h) {
  if (transmission_) return applyPowertrain(in, vx, h);
  double pi = 0;
  if (speed_) pi = speed_->torque(vx, h, time());
  for (int w = 0; w < 4; ++w) {
    const vehicle::WheelSpec& ws = vehicle().wheel(w);
    const double drive = ws.driven ? in.throttle * vehicle().spec.maxDriveTorque + pi : 0.0;
    forces_->setDriveTorque(w, drive);
    forces_->setBrakeCapacity(w, in.brake * ws.brakeTorque);
  }
}

Simulation::ChassisState Simulation::chassisState() const {
  // From the coordinates directly (no kinematic pass): the free joint holds
  // the chassis position and attitude, its velocity is in chassis axes.
  const integ::SolutionPoint& p = integrator_->current();
  if (vehicle().planar) {
    // The planar joint: (x, y, yaw) and (forward, sideways, yaw rate) of the
    // base; the centre of mass where it sits on the base at rest.
    // (A closed form holds them first.)
    const mb::Body& b = vehicle().model.bodies[vehicle().layout.base];
    const double* qb = p.q.data() + (car_ ? 0 : b.qIndex);
    const int bv = car_ ? 0 : b.vIndex;
    const double w = p.v(bv + 1), r = p.v(bv + 2);
    const Eigen::Vector3d c = vehicle().planar->comInBase;
    const double cy = pm::cos(qb[2]), sy = pm::sin(qb[2]);
    ChassisState s;
    s.com = Eigen::Vector3d(qb[0] + cy * c.x() - sy * c.y(), qb[1] + sy * c.x() + cy * c.y(), c.z());
    s.yaw = qb[2];
    s.vx = forwardSpeed();
    s.vy = w + r * c.x();
    s.yawRate = r;
    return s;
  }
  const mb::Body& ch = vehicle().model.bodies[vehicle().layout.chassis];
  const double* qc = p.q.data() + (car_ ? 0 : ch.qIndex);  // a closed form holds the free joint first
  const Eigen::Matrix3d R = Eigen::Quaterniond(qc[3], qc[4], qc[5], qc[6]).toRotationMatrix();
  const int cv = car_ ? 0 : ch.vIndex;
  const Eigen::Vector3d vb = p.v.segment<3>(cv), wb = p.v.segment<3>(cv + 3);
  ChassisState s;
  s.com = Eigen::Vector3d(qc[0], qc[1], qc[2]) + R * ch.com;
  s.yaw = pm::atan2(R(1, 0), R(0, 0));
  s.vx = forwardSpeed();
  s.vy = (vb + wb.cross(ch.com)).y();
  s.yawRate = wb.z();
  return s;
}

double Simulation::forwardSpeed() const {
  const integ::SolutionPoint& p = integrator_->current();
  if (vehicle().planar) {
    const int bv = car_ ? 0 : vehicle().model.bodies[vehicle().layout.base].vIndex;
    return p.v(bv) - p.v(bv + 2) * vehicle().planar->comInBase.y();
  }
  const mb::Body& ch = vehicle().model.bodies[vehicle().layout.chassis];
  const int cv = car_ ? 0 : ch.vIndex;
  const Eigen::Vector3d vb = p.v.segment<3>(cv), wb = p.v.segment<3>(cv + 3);
  return (vb + wb.cross(ch.com)).x();
}

void Simulation::steerToward(double command) {
  const double t = time(), tick = spec().tick;
  const double s = rack_.steerAt(t), r = rack_.rateAt(t);
  rack_.segment = {false, t, s, r, steeringAcceleration(steeringLimits_, s, r, command, tick)};
}

void Simulation::beginTick(const std::optional<DriverInput>& input) {
  state_.scriptedDriver = !input;
  if (input) {
    state_.input.steer = std::clamp(input->steer, -1.0, 1.0);
    state_.input.throttle = std::clamp(input->throttle, 0.0, 1.0);
    state_.input.brake = std::clamp(input->brake, 0.0, 1.0);
    state_.input.handbrake = std::clamp(input->handbrake, 0.0, 1.0);
    state_.input.clutch = std::clamp(input->clutch, 0.0, 1.0);
    state_.input.clutchPedal = input->clutchPedal;
    state_.input.shift = input->shift > 0 ? 1 : input->shift < 0 ? -1 : 0;
    steerToward(state_.input.steer);
  } else if (preview_ && time() >= 0) {
    const ChassisState s = chassisState();
    const double t = time();
    state_.input.steer = preview_->steer({s.com.x(), s.com.y(), s.yaw, s.vx, s.vy, s.yawRate, rack_.steerAt(t), rack_.rateAt(t)});
    steerToward(state_.input.steer);
  } else if (follower_ && time() >= 0) {
    const ChassisState s = chassisState();
    state_.input.steer = follower_->steer(s.com.x(), s.com.y(), s.yaw, s.vx, s.yawRate, spec().tick);
    steerToward(state_.input.steer);
  } else if (spec().steering.asDriverCommand && time() >= 0) {
    // Sampled in the middle of the tick, away from a square signal's edges.
    state_.input.steer = std::clamp(steering_->at(time() + 0.5 * spec().tick).value, -1.0, 1.0);
    steerToward(state_.input.steer);
  }
  if (policy_) chooseRung();
}

}  // namespace bdfcar::scenario
