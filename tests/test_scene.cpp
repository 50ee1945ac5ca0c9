// Cars in one scene (scenario/simulation.h: Scene, buildWorld with a scene):
// the terrain is built once and shared, and each car, stepped in turn with
// the other, runs bit for bit as it runs alone (no contact between cars
// yet). A scenario on another ground cannot join the scene.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scenario/scenario_spec.h"
#include "scenario/simulation.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

scenario::ScenarioSpec spec(const char* scenario, const char* vehicle, const char* fidelity) {
  scenario::ScenarioSpec s = scenario::loadScenarioFile(asset(scenario));
  s.vehicleFile = asset(vehicle);
  EXPECT_TRUE(scenario::parseFidelity(fidelity, s.fidelity));
  return s;
}

// The manoeuvre's samples after each driver tick of the scenario's driver.
void tick(scenario::Simulation& sim, std::vector<double>& out) {
  sim.beginTick(std::nullopt);
  for (int k = 0; k < sim.stepsPerTick(); ++k) ASSERT_TRUE(sim.step().ok());
  const vehicle::VehicleSample s = sim.sample();
  out.insert(out.end(), {s.t, s.com.x(), s.com.y(), s.com.z(), s.yaw, s.yawRate, s.ay, s.vx, s.Fz[0], s.Fy[3]});
}

TEST(Scene, TwoCarsEachRunAsAlone) {
  // Two cars on the flat road: the sedan's linkage in the J-turn, and the
  // paper car's planar rung in the lane change.
  const scenario::ScenarioSpec a = spec("scenarios/jturn.toml", "vehicles/sedan.toml", "linkage");
  const scenario::ScenarioSpec b = spec("scenarios/lane_change.toml", "vehicles/paper.toml", "planar");
  constexpr int kTicks = 250;
  std::vector<double> aloneA, aloneB;
  {
    scenario::Simulation simA(a);
    simA.prepare();
    for (int i = 0; i < kTicks; ++i) tick(simA, aloneA);
    scenario::Simulation simB(b);
    simB.prepare();
    for (int i = 0; i < kTicks; ++i) tick(simB, aloneB);
  }
  const std::shared_ptr<const scenario::Scene> scene = scenario::buildScene(a);
  scenario::Simulation simA(scenario::buildWorld(a, scene)), simB(scenario::buildWorld(b, scene));
  EXPECT_EQ(simA.world().terrain.get(), scene->terrain.get());
  EXPECT_EQ(simB.world().terrain.get(), scene->terrain.get());
  simA.prepare();
  simB.prepare();
  std::vector<double> togetherA, togetherB;
  for (int i = 0; i < kTicks; ++i) {
    tick(simA, togetherA);
    tick(simB, togetherB);
  }
  ASSERT_EQ(togetherA.size(), aloneA.size());
  for (size_t i = 0; i < aloneA.size(); ++i) ASSERT_EQ(togetherA[i], aloneA[i]) << "car A, value " << i;
  for (size_t i = 0; i < aloneB.size(); ++i) ASSERT_EQ(togetherB[i], aloneB[i]) << "car B, value " << i;
  // They are two cars: different places and motions.
  EXPECT_NE(togetherA.back(), togetherB.back());
}

TEST(Scene, ACarOnAnotherGroundCannotJoin) {
  const scenario::ScenarioSpec flat = spec("scenarios/jturn.toml", "vehicles/sedan.toml", "planar");
  scenario::ScenarioSpec hill = spec("scenarios/proving_ground/hill_stop.toml", "vehicles/sedan.toml", "planar");
  const std::shared_ptr<const scenario::Scene> scene = scenario::buildScene(flat);
  try {
    scenario::buildWorld(hill, scene);
    ADD_FAILURE() << "a car on the proving ground joined the flat road's scene";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("proving_ground.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("flat.toml"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace bdfcar
