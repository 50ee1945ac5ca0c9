// The planar rung of the fidelity ladder: a two-track model with roll and
// pitch load transfer, derived from the kinematic rung (and so from the
// linkage) with no hand-entered parameter.
//
//  - The base (the unsprung masses of the unsteered corners, on level ground)
//    moves in the plane of the road: x, y and yaw on a planar joint. The
//    sprung body rolls and pitches on it about a universal joint at the roll
//    axis height under its centre of mass; the steered carriers are tables of
//    the rack travel at their static travel; the same wheels spin on them.
//    12 coordinates and 3 rack drivers for the reference sedan (kinematic: 17).
//  - No vertical motion: each tyre's normal load is its static load, plus the
//    corner spring under the rolled and pitched body (the wheel rate from the
//    sweep in series with the tyre's vertical rate, and the damper through
//    its motion ratio), plus the load the roll centres carry (each axle's
//    lateral tyre force times its roll-centre height over its track; the
//    longitudinal one over the wheelbase at the roll axis height).
//  - Derived at the static equilibrium of the kinematic model on level
//    ground: static loads, wheel rates, roll-centre heights from the lateral
//    motion of each contact point with travel (the instant-centre
//    construction), steering tables from the kinematic tables at the static
//    travel, masses: the sprung body is the kinematic chassis, the unsprung
//    masses its carriers.
// Not modelled (documented in docs/DESIGN.md): heave, the unsprung masses'
// own load transfer, anti-dive and anti-squat geometry (the pitch axis is
// the roll axis), camber from roll, slopes and bumps (level ground only).
#pragma once

#include <string>

#include "vehicle/kinematic_model.h"

namespace bdfcar::vehicle {

struct PlanarDerivation {
  Vehicle vehicle;                      // the planar model (vehicle.planar holds its load transfer)
  KinematicDerivation kinematic;        // what it was derived from
  std::array<double, 4> wheelRate{};    // N/m, suspension alone at the static travel
  std::array<double, 4> staticTravel{}; // m, the kinematic model's at rest
  double rollStiffness = 0;             // N m/rad, both axles, corner springs
  double sprungMass = 0;                // kg
  double sprungComHeight = 0;           // m above the ground at rest
  // The roll and pitch axis: the instant-centre construction's height, and
  // the steady roll per lateral acceleration it was identified to (the
  // kinematic rung's; 0: not identified, the construction's axis kept).
  // scenario/planar_rung.h.
  double geometricAxisHeight = 0;       // m
  double kinematicRollGradient = 0;     // rad per m/s^2
};

// Throws mb::ModelError naming what cannot be derived (see deriveKinematic;
// also: no unsteered axle to carry the base, no static equilibrium).
PlanarDerivation derivePlanar(const Vehicle& linkage);

// Moves the planar model's roll and pitch axis (the sprung body's joint and
// the corner springs' points) and both roll centres by the same height, so
// that the axis is at this height above the ground.
void setPlanarRollAxis(Vehicle& planar, double axisHeight);

// Sets the height of the planar model's road plane (the ground at the start).
void setPlanarGround(Vehicle& planar, double groundZ);

// One line per figure, for `bdfcar info --fidelity planar` and the report.
std::string describePlanar(const PlanarDerivation& d);

}  // namespace bdfcar::vehicle
