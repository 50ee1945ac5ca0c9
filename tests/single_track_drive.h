// The single-track car (vehicle/single_track.h) driven from rest at a
// constant speed with a road-wheel angle given in time, by classical RK4 at
// 1 ms: the reference the calibrations and the preview driver are tested on.
#pragma once

#include <cmath>

#include "scenario/standard_tests.h"
#include "vehicle/single_track.h"

namespace bdfcar::test {

// The car at speed u from rest, road-wheel angle delta(t), by RK4: the time
// history (steer: delta(t) in the unit `toSteer` turns it into).
template <class Delta>
scenario::TimeHistory drive(const vehicle::SingleTrack& c, double u, double T, Delta delta, double toSteer) {
  scenario::TimeHistory h;
  const double dt = 1e-3;
  double vy = 0, r = 0;
  for (long i = 0; i <= std::lround(T / dt); ++i) {
    const double t = i * dt;
    h.t.push_back(t);
    h.steer.push_back(toSteer * delta(t));
    h.ay.push_back(c.lateralAcceleration(u, vy, r, delta(t)));
    h.yawRate.push_back(r);
    h.speed.push_back(u);
    double k1v, k1r, k2v, k2r, k3v, k3r, k4v, k4r;
    c.derivatives(u, vy, r, delta(t), k1v, k1r);
    c.derivatives(u, vy + 0.5 * dt * k1v, r + 0.5 * dt * k1r, delta(t + 0.5 * dt), k2v, k2r);
    c.derivatives(u, vy + 0.5 * dt * k2v, r + 0.5 * dt * k2r, delta(t + 0.5 * dt), k3v, k3r);
    c.derivatives(u, vy + dt * k3v, r + dt * k3r, delta(t + dt), k4v, k4r);
    vy += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    r += dt / 6 * (k1r + 2 * k2r + 2 * k3r + k4r);
  }
  return h;
}


}  // namespace bdfcar::test
