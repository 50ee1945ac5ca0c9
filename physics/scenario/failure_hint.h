// What a failed step says besides the integrator's reason ("Newton did not
// converge ..."): what the car was doing at the last accepted step (an
// impact: a tyre carrying several times its share of the weight; all wheels
// in the air) and the settings that follow such motion, so that a user whose
// car drove off a 1 m drop learns what happened and what to try.
#pragma once

#include <string>

#include "scenario/scenario_spec.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

// A tyre carrying more than this many times a quarter of the car's weight
// is called an impact (a firm kerb strike peaks near 2.5, a landing higher).
inline constexpr double kImpactLoadRatio = 3.0;

// " (hint: ...)": `last` is the sample of the last accepted step, `weight` the
// car's weight (N), `integrator` the run's settings.
std::string failureHint(const vehicle::VehicleSample& last, double weight, const IntegratorSpec& integrator);

}  // namespace bdfcar::scenario
