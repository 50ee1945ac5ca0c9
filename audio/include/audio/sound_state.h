// What the car sounds like in one driver tick: the few physical quantities
// the synthesiser (car_synth.h) turns into an engine note, tyre squeal,
// wind and rolling noise, a gear shift and a bump. Plain data, SI units; the
// application fills it from the simulation (app/session/car_sound.h).
#pragma once

#include <array>

namespace bdfcar::audio {

struct SoundState {
  double engineRpm = 0;    // crank speed, rpm (0: engine off)
  double engineLoad = 0;   // [0, 1]: torque over full load at this speed (the throttle where unknown)
  int cylinders = 4;       // four-stroke: the firing frequency is rpm / 60 * cylinders / 2
  double speed = 0;        // m/s of the car over the ground
  // Per tyre: its combined slip sqrt(kappa^2 + tan(alpha)^2) and its share
  // of the car's weight it carries now (0 in the air).
  std::array<double, 4> slip{}, load{};
  bool shifting = false;   // a gear change under way (the clutch open)
  double bump = 0;         // m/s: the largest suspension travel rate this tick (a hit)
};

// The firing frequency of a four-stroke engine (Hz): the engine note's fundamental.
inline double firingFrequency(double rpm, int cylinders) { return rpm / 60.0 * cylinders / 2.0; }

}  // namespace bdfcar::audio
