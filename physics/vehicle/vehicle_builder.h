// Turns a VehicleSpec into a multibody Model (the topology comes from the
// data) and a layout: which bodies and coordinates are the chassis, the
// rack, the wheels, for the forces, the inputs and the telemetry.
#pragma once

#include <array>
#include <optional>

#include "multibody/data.h"
#include "multibody/model.h"
#include "vehicle/vehicle_spec.h"

namespace bdfcar::vehicle {

struct WheelLayout {
  int spindle = -1;        // body index of the spindle (wheel)
  int carrier = -1;        // its parent body (upright / knuckle)
  int spinV = -1;          // velocity index of the spin joint
  double spinSign = 1.0;   // +1 if a positive spin coordinate turns the wheel about its +y (left) axis
};

// A suspension member for drawing: a segment between two body-fixed points.
struct LinkDrawing {
  int bodyA = -1, bodyB = -1;  // -1 = ground (unused)
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();  // in the body frames
  LinkKind kind = LinkKind::Link;
};

struct VehicleLayout {
  int chassis = 0;             // the sprung body (telemetry, drag, drive reaction)
  int base = 0;                // the body on the ground joint: the chassis, or a planar model's base
  int rack = -1, rackQ = -1, rackV = -1;
  double rackAxisSign = 1.0;   // rack coordinate direction along chassis +y
  int rackDriverSlot = 0;
  std::array<WheelLayout, 4> wheels;  // FL, FR, RL, RR (the same order as VehicleSpec::wheels)
  std::vector<LinkDrawing> links;
  // Suspension channels (telemetry): the corner each spring-damper moves
  // with (-1: none, e.g. a bar between two wheels), and each wheel centre
  // in the chassis frame at the linkage's design, from which travel counts.
  std::vector<int> springCorner;
  std::array<Vec3, 4> wheelCentreAtDesign{};
  int cutJointEquations = 0;   // rows from cut joints (without the rack driver)
  // A powertrain's engine (-1: none): a rotor on a revolute joint about
  // chassis x, whose joint coordinate is the crank angle.
  int engine = -1, engineQ = -1, engineV = -1;
  int spinCoordinates = 0;
};

// The rungs of the fidelity ladder (docs/DESIGN.md): the linkage as the
// vehicle file describes it, or models derived from it (kinematic_model.h).
enum class Fidelity { Linkage, Kinematic, Planar };
const char* fidelityName(Fidelity f);

// A planar model's load transfer (planar_model.h), derived from the linkage:
// the tyre loads are the static ones plus what the corner springs under the
// rolled and pitched body and the roll centres carry. Corners FL FR RL RR,
// axles front and rear.
struct PlanarLoads {
  std::array<double, 4> staticLoad{};  // N
  std::array<double, 4> rate{};        // N/m, wheel rate in series with the tyre's vertical rate
  std::array<double, 4> damping{};     // N s/m, at the wheel
  std::array<double, 4> staticTravel{};      // m, the kinematic model's suspension travel at rest
  std::array<double, 4> suspensionShare{};   // of a corner's deflection taken by the suspension (the rest: the tyre)
  std::array<Vec3, 4> sprungPoint{};   // corner point on the sprung body (its frame), above the contact point
  std::array<Vec3, 4> basePoint{};     // the same point on the base (its frame)
  std::array<double, 2> rollCentreHeight{};  // m above the ground
  std::array<double, 2> track{};       // m, between the contact points
  double wheelbase = 0;                // m
  double axisHeight = 0;               // m, roll and pitch axes above the ground
  Vec3 comInBase = Vec3::Zero();       // the vehicle's centre of mass in the base frame at rest
  std::array<double, 4> restTravel{};  // m, wheelCentreTravel at rest (the base and body unrolled)
  // Per axle, the anti-roll bars' rate on the corners' deflection (suspension
  // and tyre in series): what brings the axle's roll stiffness from the
  // corner springs' to that of (suspension + bar) in series with the tyres.
  std::array<double, 2> barRate{};     // N/m
  // What the linkage's kinematics do to the wheel's attitude as it travels:
  // the carrier's rotation per metre of wheel travel at the static travel
  // (rad/m, chassis frame; toe: bump and roll steer, camber gain, caster
  // change), applied to the tyre's wheel kinematics with the travel the
  // corner spring's deflection gives, over the sprung body's own roll and
  // pitch relative to the base (the wheels ride on the base).
  std::array<Vec3, 4> turnPerTravel{};
  Mat3 sprungRest = Mat3::Identity();  // the sprung body's axes in the base frame at zero roll and pitch
};

// A plain value: copies stay valid (the layout holds indices, no pointers).
struct Vehicle {
  Fidelity fidelity = Fidelity::Linkage;
  VehicleSpec spec;
  mb::Model model;
  VehicleLayout layout;
  std::optional<PlanarLoads> planar;   // a planar model's tyre loads
  // The data of wheel w (0..3: FL, FR, RL, RR).
  const WheelSpec& wheel(int w) const { return spec.wheels[w]; }
};

// Builds the model; throws mb::ModelError naming the offending element.
Vehicle buildVehicle(const VehicleSpec& spec);

// For the models derived from a linkage (kinematic_model.h, planar_model.h):
// a driver tying coordinate `coordinate` of `body` to the rack signal, and the
// layout's indices once the model is built (rack, spins; no loop equations).
void addRackDriver(mb::ModelBuilder& builder, const std::string& name, int body, int coordinate = 0);
void indexDerivedLayout(Vehicle& v, double rackAxisSign);

// A powertrain's engine as a body of the model (none without a powertrain):
// a rotor of the engine's inertia about chassis x on a revolute joint in the
// chassis body `chassis`, at its centre of mass `com` (its own frame).
void addEngine(mb::ModelBuilder& builder, const VehicleSpec& spec, int chassis, const Vec3& com);
// The engine's indices once the model is built (VehicleLayout::engine).
void indexEngine(Vehicle& v);

// Sets the rack coordinate of q (and every coordinate a rack driver ties to
// it: a kinematic model's steered corners) to x, m along the rack's axis.
void setRackTravel(const Vehicle& v, Eigen::VectorXd& q, double x);

// Wheel w's centre along chassis z, relative to the chassis, minus its
// place at the linkage's design (VehicleLayout::wheelCentreAtDesign), for
// the positions of d: + bump. The telemetry's suspension travel; a planar
// model's wheel does not compress its tyre, so its suspension takes only its
// share of this (PlanarLoads::suspensionShare).
double wheelCentreTravel(const Vehicle& v, const mb::Data& d, int w);
// The suspension's travel of wheel w (the telemetry's travel_XX_m): the
// wheel-centre travel, of which a planar model's suspension takes its share.
double suspensionTravel(const Vehicle& v, const mb::Data& d, int w);

// Positions at design with the chassis frame at (0, 0, designHeight) (a
// planar model: its base at the origin of its plane, unrolled).
Eigen::VectorXd designPositions(const Vehicle& v);

}  // namespace bdfcar::vehicle
