// The kinematic rung of the fidelity ladder, derived from a linkage vehicle
// with no hand-entered parameter:
//  - a quasi-static sweep of the linkage (chassis held, each wheel centre
//    moved vertically by s relative to the chassis, the rack at r) tabulates
//    each wheel carrier's pose relative to the chassis and each spring-
//    damper's length over (s, r) for steered corners, over s for the others;
//  - the model is the chassis (free joint), the rack (prismatic, prescribed
//    as in the linkage), one carrier per corner on a tabulated joint (travel,
//    and rack travel tied to the rack by a driver at the steered corners) and
//    the same wheels on their spin joints: 6 + 1 + 4 (+2) + 4 coordinates;
//  - springs and dampers act through the tabulated lengths (F dL/dc: the
//    motion ratio of the sweep, at every travel);
//  - each carrier's mass makes its corner's generalised mass along travel
//    equal to the linkage's (N^T M N over the sweep's travel direction N);
//    the chassis takes the rest: total mass, centre of mass and inertia at
//    design are the linkage's;
//  - the links' weight along travel that this lumping moves (the linkage's
//    sum m dz/ds less the carrier's) acts on each corner's first spring as
//    its lumped weight (exact at design): the model rests where the linkage
//    rests.
// The same tyres, terrain, steering and telemetry apply. deriveKinematic also
// checks the tables against the linkage between the grid nodes.
#pragma once

#include <array>
#include <string>

#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

// The tables against the linkage at points between the grid nodes (the
// worst point of all four corners).
struct KinematicCheck {
  int points = 0;                 // linkage configurations compared
  double wheelCentre = 0;         // m, largest wheel-centre position difference
  double camber = 0;              // rad, largest camber difference
  double toe = 0;                 // rad, largest toe / steer angle difference
  double travelRange = 0;         // m, tabulated wheel travel +-
  double rackRange = 0;           // m, tabulated rack travel +-
};

struct KinematicDerivation {
  Vehicle vehicle;                        // the kinematic model
  KinematicCheck check;
  std::array<double, 4> carrierMass{};    // kg, per corner (FL FR RL RR)
  std::array<double, 4> linkageTravelMass{};  // kg, the linkage's generalised mass along each travel
  std::array<bool, 4> steered{};          // corner tabulated over the rack too
  int sweepConfigurations = 0;            // linkage assemblies in the sweep
  bool fromCache = false;                 // the sweep and its check read from the cache (derivation_cache.h)
  std::string cacheFile;                  // the cache entry (empty: the cache is off)
};

// Tabulation density (nodes per coordinate); the defaults keep the tables
// within micrometres of the linkage for the reference sedan (see the check).
struct KinematicGrid {
  int travelNodes = 41;
  int rackNodes = 25;
  double travel = 0.12;         // m, +- wheel travel (reduced if the linkage cannot reach it)
  double rackMargin = 1.1;      // rack range = margin x the rack travel at full steer
};

// Throws mb::ModelError naming what cannot be derived (a spring that moves
// with no single wheel, a linkage that cannot be swept, a non-physical
// chassis after the carriers take their masses).
KinematicDerivation deriveKinematic(const Vehicle& linkage, const KinematicGrid& grid = {});

// One line per figure, for `bdfcar info --fidelity kinematic` and the report.
std::string describeKinematic(const KinematicDerivation& d);

}  // namespace bdfcar::vehicle
