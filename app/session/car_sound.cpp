#include "session/car_sound.h"

#include <algorithm>
#include <cmath>

#include "vehicle/powertrain.h"

namespace bdfcar::app {

namespace {
// A notional engine for a car without a powertrain: idle, and this many rpm
// per m/s (a top gear: 2,600 rpm at 100 km/h).
constexpr double kIdleRpm = 850.0, kRpmPerSpeed = 63.0;
}  // namespace

audio::SoundState CarSound::update(const DriveSession& session) {
  const scenario::Simulation& sim = session.simulation();
  const vehicle::VehicleSample& s = session.lastSample();
  const vehicle::Vehicle& v = sim.vehicle();
  audio::SoundState out;
  out.speed = s.speed;
  if (sim.transmission()) {
    const scenario::PowertrainChannels p = sim.powertrainChannels();
    out.engineRpm = std::max(0.0, p.engineRpm);
    const double full = vehicle::fullLoadTorque(v.spec.powertrain->engine, out.engineRpm * M_PI / 30.0);
    out.engineLoad = full > 0 ? std::clamp(p.engineTorque / full, 0.0, 1.0) : p.throttle;
    out.shifting = sim.transmission()->shifting();
  } else {
    out.engineRpm = kIdleRpm + kRpmPerSpeed * std::abs(s.speed);
    const scenario::DriverInput in = sim.lastInput();
    const double maxDrive = v.spec.maxDriveTorque;
    double drive = 0;
    for (int w = 0; w < 4; ++w) drive = std::max(drive, std::abs(s.driveTorque[w]));
    out.engineLoad = std::clamp(std::max(in.throttle, maxDrive > 0 ? drive / maxDrive : 0.0), 0.0, 1.0);
  }
  const double share = v.model.totalMass() * v.model.gravity.norm() / 4;
  double bump = 0;
  const bool onward = s.t > time_;  // not a rewind, a reset or the first tick
  for (int w = 0; w < 4; ++w) {
    out.slip[w] = std::hypot(s.kappa[w], std::tan(std::clamp(s.alpha[w], -1.5, 1.5)));
    out.load[w] = s.inContact[w] ? std::clamp(s.Fz[w] / share, 0.0, 1.5) : 0.0;
    if (onward && time_ > -1e299) bump = std::max(bump, std::abs(s.travel[w] - travel_[w]) / (s.t - time_));
    travel_[w] = s.travel[w];
  }
  out.bump = bump;
  time_ = s.t;
  return out;
}

}  // namespace bdfcar::app
