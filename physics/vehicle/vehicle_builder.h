// Turns a VehicleSpec into a multibody Model (the topology comes from the
// data) and a layout: which bodies and coordinates are the chassis, the
// rack, the wheels, for the forces, the inputs and the telemetry.
#pragma once

#include <array>

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
  int chassis = 0;
  int rack = -1, rackQ = -1, rackV = -1;
  double rackAxisSign = 1.0;   // rack coordinate direction along chassis +y
  int rackDriverSlot = 0;
  std::array<WheelLayout, 4> wheels;  // FL, FR, RL, RR (the same order as VehicleSpec::wheels)
  std::vector<LinkDrawing> links;
  int cutJointEquations = 0;   // rows from cut joints (without the rack driver)
  int spinCoordinates = 0;
};

// The rungs of the fidelity ladder (docs/DESIGN.md): the linkage as the
// vehicle file describes it, or models derived from it (kinematic_model.h).
enum class Fidelity { Linkage, Kinematic };
const char* fidelityName(Fidelity f);

// A plain value: copies stay valid (the layout holds indices, no pointers).
struct Vehicle {
  Fidelity fidelity = Fidelity::Linkage;
  VehicleSpec spec;
  mb::Model model;
  VehicleLayout layout;
  // The data of wheel w (0..3: FL, FR, RL, RR).
  const WheelSpec& wheel(int w) const { return spec.wheels[w]; }
};

// Builds the model; throws mb::ModelError naming the offending element.
Vehicle buildVehicle(const VehicleSpec& spec);

// Sets the rack coordinate of q (and every coordinate a rack driver ties to
// it: a kinematic model's steered corners) to x, m along the rack's axis.
void setRackTravel(const Vehicle& v, Eigen::VectorXd& q, double x);

// Positions at design with the chassis frame at (0, 0, designHeight).
Eigen::VectorXd designPositions(const Vehicle& v);

}  // namespace bdfcar::vehicle
