// The steering ratio a driver steers by (vehicle::roadWheelAnglePerSteer:
// the path follower's and the preview driver's, the HUD's and a wheel
// device's, road-wheel angles in scenarios) against a second algorithm, the
// K&C rig's steering ratio at centre (wheels held at design height, a
// central difference a fiftieth as wide), and the same figure read from
// each rung derived from the linkage (its tables, not the linkage's loops):
// one car, one ratio. Measured with the suspension left free to close the
// loops, the sedan's was 7 % off the rig's and its derived rungs'.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "scenario/simulation.h"
#include "test_files.h"
#include "vehicle/kc_rig.h"
#include "vehicle/kinematic_model.h"
#include "vehicle/motion_ratio.h"
#include "vehicle/planar_model.h"
#include "vehicle/vehicle_file.h"

using namespace bdfcar;

TEST(SteeringRatio, IsTheKcRigsAtCentreOnTheLinkageAndOnItsDerivedRungs) {
  for (const std::string file : {"vehicles/sedan.toml", "vehicles/paper.toml", "vehicles/double_wishbone.toml",
                                 "vehicles/sedan_roll_steer.toml"}) {
    const vehicle::Vehicle linkage = vehicle::buildVehicle(vehicle::loadVehicleFile(test::asset(file)));
    const double full = linkage.spec.steering.steeringWheelFull;
    const double perSteer = vehicle::roadWheelAnglePerSteer(linkage);
    const double rig = vehicle::runKcRig(linkage).steeringRatio;
    // The rig's slope at centre against a secant over +-0.05 of steer: they
    // differ by the steering's cubic term over that width, below 0.2 % on a
    // rack and pinion this close to linear.
    EXPECT_NEAR(full / perSteer, rig, 2e-3 * rig) << file;
    // The derived rungs through their splines over travel and rack travel.
    const double kinematic = vehicle::roadWheelAnglePerSteer(vehicle::deriveKinematic(linkage).vehicle);
    const double planar = vehicle::roadWheelAnglePerSteer(vehicle::derivePlanar(linkage).vehicle);
    EXPECT_NEAR(kinematic, perSteer, 1e-3 * perSteer) << file;
    EXPECT_NEAR(planar, perSteer, 1e-3 * perSteer) << file;
  }
}

// The preview driver steers by the linkage's single-track model on every
// rung (it read the running rung's vehicle sheet, which only a linkage has,
// and stopped with "derived from a linkage model only"), and the car it
// steers passes the ISO 3888-1 course on each.
TEST(SteeringRatio, ThePreviewDriverDrivesEveryRungThroughTheCourse) {
  for (const vehicle::Fidelity rung : {vehicle::Fidelity::Kinematic, vehicle::Fidelity::Planar}) {
    scenario::ScenarioSpec spec = scenario::loadScenarioFile(test::asset("scenarios/iso_lane_change.toml"));
    spec.pathFollower.law = scenario::PathFollowerSpec::Law::Preview;
    spec.fidelity.suspension = rung;
    scenario::Simulation sim(spec);
    EXPECT_EQ(sim.carSteering().roadWheelFull,
              vehicle::roadWheelAnglePerSteer(vehicle::buildVehicle(vehicle::loadVehicleFile(spec.vehicleFile))))
        << "the car's steering is its linkage's";
    const scenario::RunResult r = scenario::runScenario(sim, {});
    ASSERT_TRUE(r.ok) << vehicle::fidelityName(rung) << ": " << r.failure;
    ASSERT_TRUE(r.course.has_value());
    EXPECT_TRUE(r.course->passed) << vehicle::fidelityName(rung) << ": left the course at x = " << r.course->firstFailureX;
    EXPECT_EQ(r.course->coneHits, 0) << vehicle::fidelityName(rung);
  }
}
