// A kinematics-and-compliance (K&C) rig, kinematics only: quasi-static
// sweeps of a linkage vehicle on the rig of linkage_sweep.h (chassis held at
// its design pose, wheel centres moved vertically relative to it, the rack
// moved), and the standard numbers read from them at design.
//
// Frame: the vehicle frame on the ground (x forward, y left, z up, z = 0 the
// ground at the design height, under the chassis frame). Every value is SI
// (m, rad); degrees only at the output edge. Per-corner arrays are FL FR RL
// RR, per-axle arrays front, rear. Conventions (docs/VEHICLES.md, "K&C rig"):
//  - travel: wheel centre up relative to the chassis (+ bump);
//  - body roll: about +x (ISO 8855), + = left side up, i.e. left wheels in
//    rebound, right wheels in bump by track/2 x roll;
//  - steer angle: about +z, + = wheel pointing left; toe: + toe-in;
//  - camber: + top of the wheel leaning outward (relative to the chassis;
//    roll camber is relative to the ground);
//  - contact point: where the wheel's plane, the ground and the vertical
//    plane through the spin axis meet (a rigid wheel on the design ground).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

// One curve column: a name and its SI unit ("m", "rad", "1", "m/m").
struct KcColumn {
  std::string name, unit;
  std::vector<double> values;
};

// A sweep: its first column is the swept variable.
struct KcTable {
  std::string name;  // parallel_travel, roll, steering
  std::vector<KcColumn> columns;
};

// The numbers at design, per corner.
struct KcCorner {
  double toe = 0, camber = 0;   // rad
  double bumpSteer = 0;         // rad of toe per m of travel (parallel)
  double camberGain = 0;        // rad of camber per m of travel (parallel)
  double rollSteer = 0;         // rad of toe per rad of body roll
  double rollCamber = 0;        // rad of camber to the ground per rad of body roll
  double halfTrackChange = 0;   // m of outward contact-point motion per m of travel
  double wheelRate = 0;         // N/m, the corner's springs (not the anti-roll bars), parallel travel
  std::vector<std::string> springNames;
  std::vector<double> motionRatio;  // dL/ds of each spring-damper moving with this wheel
  // Steering axis (steered corners; NaN otherwise): the instantaneous axis of
  // the carrier's motion relative to the chassis when the rack moves and the
  // corner's first spring-damper keeps its length (the suspension held).
  bool steered = false;
  double caster = 0;            // rad, + axis top rearward
  double kingpinInclination = 0;// rad, + axis top inboard
  double scrubRadius = 0;       // m, + axis meets the ground inboard of the contact point
  double trail = 0;             // m, + axis meets the ground ahead of the contact point
};

struct KcAxle {
  double track = 0;             // m, between the contact points
  double trackChange = 0;       // m/m of parallel travel
  double rollCentre = 0;        // m above the ground
  double rollCentreMigration = 0;  // m of roll-centre height per m of parallel travel
  double rollSteer = 0;         // rad of mean steer angle per rad of body roll (+ steers toward the rising side)
};

struct KcResult {
  std::array<KcCorner, 4> corner;
  std::array<KcAxle, 2> axle;
  double wheelbase = 0;         // m, between the axles' mean contact points
  double comHeight = 0;         // m, the whole vehicle's centre of mass above the ground
  double brakeFront = 0;        // share of the brake torque on the front wheels
  double antiDive = 0;          // %, front, braking (outboard brakes: contact-point path); NaN without brakes
  double antiSquat = 0;         // %, rear, driving (path by the drive reaction); NaN without a driven rear wheel
  double steeringRatio = 0;     // steering-wheel angle per mean front road-wheel angle, at centre
  double ackermann = 0;         // %, at 10 deg inner road-wheel angle (NaN: not reached)
  double travelRange = 0;       // m, the parallel sweep's +- travel
  double rollRange = 0;         // rad, the roll sweep's +- body roll
  std::vector<KcTable> tables;  // parallel_travel, roll, steering
};

struct KcRigSettings {
  double travel = 0.08;         // m, +- parallel travel (reduced while the linkage cannot reach it)
  double roll = 0.0524;         // rad, +- body roll (3 deg; reduced with the travel)
  int points = 33;              // samples per sweep
};

// Throws mb::ModelError if the vehicle is not a linkage that can be swept.
KcResult runKcRig(const Vehicle& linkage, const KcRigSettings& settings = {});

}  // namespace bdfcar::vehicle
