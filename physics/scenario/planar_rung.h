// The planar rung as scenes run it: derived from the linkage through the
// kinematic rung (vehicle/planar_model.h), then its roll and pitch axis
// identified from the kinematic rung's own steady roll.
//
// Why: the planar rung rolls about one axis through the roll centres of the
// instant-centre construction, and the tyres' loads follow from that axis
// and the corner springs. The linkage's roll is not that simple (its roll
// centres move as each side travels, the links carry lateral forces into
// the body at their own heights): on the reference sedan the construction's
// axis (6 cm above the ground) gives 15 % less steady roll than the linkage
// and the reference data show. The axis is therefore found as the height at
// which the planar rung's steady roll per lateral acceleration equals the
// kinematic rung's in a step steer at about 0.3 of the tyres' limit (a few
// short runs: secant iterations on the axis height), the roll centres moved
// with it (the axis carries past the springs what the roll centres carry).
// No parameter is entered by hand; the certificate then measures the rung.
#pragma once

#include "scenario/scenario_spec.h"
#include "vehicle/planar_model.h"

namespace bdfcar::scenario {

// Throws mb::ModelError as derivePlanar does. Kept per process for the same
// vehicle file, settings and integrator.
vehicle::PlanarDerivation derivePlanarRung(const ScenarioSpec& scene, const vehicle::Vehicle& linkage);

// The identification alone, on a derivation (exposed for the tests).
void identifyRollAxis(const ScenarioSpec& scene, const vehicle::Vehicle& linkage, vehicle::PlanarDerivation& p);

}  // namespace bdfcar::scenario
