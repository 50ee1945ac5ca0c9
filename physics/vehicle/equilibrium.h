// Assembly and static equilibrium of a vehicle on the road.
//  assemble: Gauss-Newton on Phi(q) = 0 (minimum-norm corrections of the free
//    coordinates) so that hardpoint round-off closes every loop.
//  settleStatic: Newton on F(q, 0, 0, lambda) = 0, Phi(q) = 0 with the chassis
//    x, y, yaw, the wheel spins and the rack held (they have no restoring
//    force at rest); the result is the static ride height and wheel loads.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "integrator/dae.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_forces.h"

namespace bdfcar::vehicle {

struct EquilibriumReport {
  bool converged = false;
  int iterations = 0;
  double forceResidual = 0;        // largest |F| on the free coordinates, N or N m
  double constraintResidual = 0;   // largest |Phi|
  double chassisHeight = 0;        // chassis reference frame above the ground, m
  double comHeight = 0;            // chassis centre of mass above the ground, m
  double roll = 0, pitch = 0;      // rad
  std::array<double, 4> wheelLoads{};  // Fz FL FR RL RR, N
  double totalLoad = 0, weight = 0;    // N
  std::string message;
};

// Closes the loops moving every coordinate except the chassis and rack ones.
bool assemble(const Vehicle& v, integ::Dae& dae, double t, integ::Vec& q, std::string& message);

// Where an assembly from `design` (the vehicle's design positions, placed
// anywhere) to `assembled` moved a body far from its design pose relative to
// the chassis (more than kMaxAssemblyMove or kMaxAssemblyTurn): hardpoints
// that do not close the loops as drawn (a tie rod's end in the wrong place
// "assembles" with the wheels toed out 47 deg). Names the body, its file and
// line, and how far; nullopt when every body stayed near its design pose.
inline constexpr double kMaxAssemblyMove = 0.02;  // m
inline constexpr double kMaxAssemblyTurn = 0.05;  // rad (2.9 deg)
std::optional<std::string> farFromDesign(const Vehicle& v, const integ::Vec& design, const integ::Vec& assembled);

// Static equilibrium at rest from q (assembled); updates q and lambda.
EquilibriumReport settleStatic(const Vehicle& v, mb::MultibodyDae& dae, VehicleForces& forces, double t,
                               integ::Vec& q, integ::Vec& lambda);

// Tangent indices held fixed at rest: chassis x, y, yaw; wheel spins; the rack.
std::vector<int> heldCoordinates(const Vehicle& v);

}  // namespace bdfcar::vehicle
