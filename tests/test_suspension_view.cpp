// What the suspension view (the body translucent or hidden) draws on each
// rung: the kinematic model's springs where the linkage has them, and the
// planar model's corner posts leaning with the body's roll as the model
// reports it.
#include <gtest/gtest.h>

#include <cmath>

#include "multibody/kinematics.h"
#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "scenario/simulation.h"
#include "vehicle/kinematic_model.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

using vehicle::LinkKind;

// At design, a spring drawn between the kinematic model's chassis and a
// carrier has the world ends of the linkage's same spring: the carrier's pose
// comes from the corner's table, the ends from the linkage's mounts.
TEST(SuspensionView, TheKinematicModelsSpringsSitWhereTheLinkagesDo) {
  const vehicle::Vehicle link = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/sedan.toml")));
  const vehicle::Vehicle kin = vehicle::deriveKinematic(link).vehicle;
  mb::Data dl = mb::makeData(link.model), dk = mb::makeData(kin.model);
  mb::updatePositions(link.model, vehicle::designPositions(link), dl);
  mb::updatePositions(kin.model, vehicle::designPositions(kin), dk);
  int onCarrier = 0, springs = 0;
  for (const vehicle::LinkDrawing& k : kin.layout.links) {
    ASSERT_EQ(k.kind, LinkKind::Spring);
    ASSERT_EQ(k.bodyA, kin.layout.chassis);
    ++springs;
    int w = -1;
    for (int c = 0; c < 4; ++c)
      if (kin.layout.wheels[c].carrier == k.bodyB) w = c;
    if (w < 0) continue;  // to the wheel centre: the linkage's lower mount is on a member not kept
    ++onCarrier;
    const Eigen::Vector3d a = mb::pointPosition(dk, k.bodyA, k.pointA), b = mb::pointPosition(dk, k.bodyB, k.pointB);
    double nearest = 1e9;
    for (const vehicle::LinkDrawing& l : link.layout.links) {
      if (l.kind != LinkKind::Spring) continue;
      const Eigen::Vector3d la = mb::pointPosition(dl, l.bodyA, l.pointA), lb = mb::pointPosition(dl, l.bodyB, l.pointB);
      nearest = std::min(nearest, std::max((la - a).norm(), (lb - b).norm()));
    }
    EXPECT_LT(nearest, 1e-4) << "corner " << w;
  }
  EXPECT_GE(springs, 4);     // a spring at every corner
  EXPECT_GE(onCarrier, 2);   // the MacPherson struts' springs, at least
}

// The planar rung's posts (wheel centre to the sprung body, 0.6 m at
// design) in the J-turn's steady part: on each axle the left post minus the
// right one is the track times the roll angle the model reports (the body
// turns about an axis between them), to 15 %.
TEST(SuspensionView, ThePlanarModelsPostsLeanWithItsRoll) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/jturn.toml"));
  spec.fidelity = {};
  spec.fidelity.suspension = vehicle::Fidelity::Planar;
  scenario::Simulation sim(spec);
  scenario::RunOptions o;
  o.keepSamples = false;
  scenario::Run run(sim, o);
  while (!run.finished() && sim.time() < 3.5 && run.tick(std::nullopt)) {
  }
  ASSERT_FALSE(run.failed()) << run.failure();
  const vehicle::VehicleSample s = sim.sample();
  const vehicle::VehicleView v = sim.view();
  ASSERT_EQ(v.links.size(), 4u);
  ASSERT_GT(std::abs(s.roll), 0.005) << "the car should be rolling in the turn";
  double length[4];
  for (int w = 0; w < 4; ++w) {
    EXPECT_EQ(v.links[w].kind, LinkKind::Strut);
    length[w] = (v.links[w].a - v.links[w].b).norm();
    EXPECT_NEAR(length[w], 0.6, 0.05) << w;
  }
  for (int axle = 0; axle < 2; ++axle) {
    const int left = 2 * axle, right = left + 1;
    const double track = (v.wheels[left].pose.position - v.wheels[right].pose.position).norm();
    const double expected = track * std::sin(s.roll);
    EXPECT_NEAR(length[left] - length[right], expected, 0.15 * std::abs(expected)) << "axle " << axle;
  }
}

}  // namespace
}  // namespace bdfcar
