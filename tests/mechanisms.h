// Test mechanisms built in code: analytic cases and a vehicle-sized closed-loop system.
#pragma once

#include "multibody/model.h"

namespace bdfcar::test {

// A body on a revolute joint about the world y axis at the origin, centre of
// mass `length` below the pivot at q = 0. Returns the model; the pivot
// inertia is mass * (length^2 + radiusOfGyration^2).
mb::Model pendulum(double length, double mass, double radiusOfGyration);

// Planar four-bar with a massless coupler (distance cut joint): crank a at
// the origin, rocker c at (d, 0, 0), coupler b, all joints about world y.
// The crank starts at angle crank0 (radians, about +y), the rocker at the
// open-branch angle that closes the loop. No gravity (the linkage lies flat).
struct FourBar {
  mb::Model model;
  double a, b, c, d, crank0, rocker0;
};
FourBar fourBar(double a, double b, double c, double d, double crank0);

// Spatial slider-crank: crank a (revolute about world y at the origin), rod b
// on a spherical joint at the crank tip, slider on a prismatic joint along
// world x; the loop is cut by a spherical joint at the rod end. At q = 0 the
// crank points along +x and the slider sits at x = a + b.
mb::Model sliderCrank(double a, double b);

// One rigid body on a free joint, principal inertia diag(Ixx, Iyy, Izz), no gravity.
mb::Model freeBody(double mass, const Eigen::Vector3d& principalInertia);

// The paper's topology without tyres (Table 1): free chassis, rack on a
// translational joint, MacPherson front (LCA revolute, strut spherical,
// knuckle translational along the strut; ball joint and tie rod cut joints),
// rear camber arm revolute with a spherical knuckle and three distance links.
// 25 relative coordinates, 14 constraint equations, 11 degrees of freedom.
mb::Model paperTopology();

}  // namespace bdfcar::test
