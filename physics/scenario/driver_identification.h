// The preview driver's model of the car fitted to the car itself: a short
// run of the car at the scenario's speed and ground with a small steering
// step (about 2 m/s^2 by the prior model), held to steady state; each axle's
// effective cornering stiffness then follows in closed form from the steady
// yaw rate r and lateral velocity vy at road-wheel angle delta (the
// single-track model's steady state: the axle forces m u r b / L and
// m u r a / L over the slip angles delta - (vy + a r) / u and
// -(vy - b r) / u). What the tyres alone miss is in them: load transfer,
// roll and compliance steer, the steering's own compliance. A probe that
// fails or gives a non-physical answer leaves the prior as it was.
#pragma once

#include "scenario/scenario_spec.h"
#include "vehicle/single_track.h"

namespace bdfcar::scenario {

struct Scene;

struct Identification {
  vehicle::SingleTrack car;  // the prior with the fitted stiffnesses, or the prior
  bool fitted = false;
  std::string why;           // when not fitted
};

Identification identifySingleTrack(const ScenarioSpec& spec, std::shared_ptr<const Scene> scene,
                                   const vehicle::SingleTrack& prior);

}  // namespace bdfcar::scenario
