// A vehicle as plain data, parsed from assets/vehicles/*.toml by one loader
// (vehicle_file.h): bodies with their tree joints, cut joints, springs and
// dampers, wheels and tyres, steering and driveline. Right-hand parts are
// already mirrored; every point is in the chassis frame V at design
// (x forward, y left, z up). SI units.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "multibody/model.h"
#include "tyre/tyre_model.h"
#include "vehicle/powertrain_spec.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::vehicle {

using mb::Mat3;
using mb::Vec3;

struct JointSpec {
  mb::JointType type = mb::JointType::Revolute;
  std::string parent;          // body name; empty for the free joint (ground)
  Vec3 at = Vec3::Zero();      // joint location at design
  Vec3 axis = Vec3::UnitZ();   // revolute, prismatic, cylindrical
  Vec3 axisParent = Vec3::UnitX(), axisChild = Vec3::UnitY();  // universal: first fixed in parent, second in child
};

struct BodySpec {
  std::string name;
  double mass = 0;
  Vec3 com = Vec3::Zero();     // at design, chassis frame
  Mat3 inertia = Mat3::Zero(); // about the COM, chassis axes at design
  JointSpec joint;
  int line = 0;                // line in the vehicle file (for error messages)
  std::string file;            // the file it was written in (an included part's)
};

enum class CutKind { Spherical, Distance };

struct CutJointSpec {
  std::string name;
  CutKind kind = CutKind::Spherical;
  std::string bodyA, bodyB;
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();  // at design, chassis frame
  double length = -1;          // distance; < 0 = the design distance of the points
  int line = 0;
  std::string file;
};

struct SpringSpec {
  std::string name;
  std::string bodyA, bodyB;
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();
  double freeLength = 0, preload = 0;
  mb::ForceCurve spring, damper;
  double bumpLength = 0, bumpStiffness = 0, reboundLength = 0, reboundStiffness = 0;
  int line = 0;
};

// The corners in the order of every per-wheel array: front left, front
// right, rear left, rear right.
inline constexpr const char* kCornerNames[4] = {"FL", "FR", "RL", "RR"};

struct WheelSpec {
  std::string position;        // FL, FR, RL, RR
  std::string spindle;         // body on the spin (revolute) joint
  tyre::TyreParams tyre;       // one of the tyre models (tyre/tyre_model.h)
  double spinInertia = 0;      // extra inertia about the spin axis (axle shaft), kg m^2
  double brakeTorque = 0;      // at full brake, N m
  bool driven = false;
};

struct SteeringSpec {
  std::string rack;            // body on a prismatic joint along chassis y
  double rackTravelFull = 0;   // rack travel toward -y (right) at steer = +1 (full left), m
  double steeringWheelFull = 0;// steering-wheel (pinion) angle at steer = +1, rad
  // The steering system between a driver's command and the rack (power
  // assist): the rack follows the command with this response time, never
  // faster than maxRackSpeed nor with more than maxRackAcceleration.
  double responseTime = 0.03;        // s
  double maxRackSpeed = 0.15;        // m/s (about 1000 deg/s at the steering wheel of a 50 mm/rev rack)
  double maxRackAcceleration = 6.0;  // m/s^2
};

// An anti-roll bar between the two wheels of an axle: a torsion bar whose
// twist is the difference of the wheels' suspension travel. Each wheel gets
// F = rate (travel_left - travel_right) against its own travel, the chassis
// the opposite at the wheel centres: no force in heave, a roll stiffness of
// rate t^2 (t the track) in roll. Acts on every fidelity rung (vehicle_forces.h).
struct AntiRollBarSpec {
  std::string name;
  int left = 0, right = 1;     // wheel indices (FL FR or RL RR)
  double rate = 0;             // N/m at the wheel centres: torsional stiffness / lever^2
  int line = 0;
};

// Where the reaction of a drive torque goes: an inboard differential reacts
// on the chassis, a hub motor on the wheel carrier; the reference runs apply
// an external torque to the spindle with no reaction at all.
enum class DriveReaction { Chassis, Carrier, None };

struct VehicleSpec {
  std::string name, description, sourceFile;
  double designHeight = 0.5;   // chassis reference frame above the ground at design, m
  std::vector<BodySpec> bodies;      // the first is the chassis (free joint)
  std::vector<CutJointSpec> cutJoints;
  std::vector<SpringSpec> springs;
  std::vector<AntiRollBarSpec> antiRollBars;  // none on the reference sedan
  std::vector<WheelSpec> wheels;     // FL, FR, RL, RR
  SteeringSpec steering;
  double maxDriveTorque = 0;         // per driven wheel at full throttle, N m
  DriveReaction driveReaction = DriveReaction::Chassis;
  double dragArea = 0;               // aerodynamic 0.5 rho Cd A, N/(m/s)^2 (0 = none)
  // Aerodynamic lift, 0.5 rho Cl A per axle, N/(m/s)^2: + lifts (- is
  // downforce), acting on the chassis above each axle's wheel centres.
  double liftAreaFront = 0, liftAreaRear = 0;
  // A drivable car's engine, clutch, gearbox and differential; none on the
  // reference vehicles, whose speed hold drives the wheels directly.
  std::optional<PowertrainSpec> powertrain;
  VehicleGeometry geometry;          // for drawing
  std::map<std::string, Vec3> points;  // named hardpoints (left side), for reports
  // `[certificate]`: the largest worst figure (fraction of the linkage's
  // peak) each derived rung's certificate may have for this car, by rung
  // name; the tests hold every shipped file to it (scenario/rung_certificate.h).
  std::map<std::string, double> certificateRequired;
};

}  // namespace bdfcar::vehicle
