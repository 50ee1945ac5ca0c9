// The run state's byte form (scenario/run_state_bytes.h): read back, it is
// the state written (operator==, and the same bytes again); a simulation
// restored from it steps bit for bit as the one that wrote it, on the
// linkage, on `auto`'s planar rung and with a powertrain; bytes that are not
// a run state, or not one of this simulation, are refused with what is wrong
// and leave the simulation as it was.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scenario/run.h"
#include "scenario/run_state_bytes.h"
#include "scenario/scenario_spec.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

scenario::ScenarioSpec spec(const char* scenario, const char* vehicle = nullptr, bool automatic = false) {
  scenario::ScenarioSpec s = scenario::loadScenarioFile(asset(scenario));
  if (vehicle) s.vehicleFile = asset(vehicle);
  if (automatic) {
    s.fidelity.automatic = true;
    s.fidelity.errorBudget = scenario::kPlanarErrorBound;
  }
  return s;
}

// Ticks of the scenario's own driver; the yaw rate, lateral acceleration,
// speed and rung after each.
std::vector<double> drive(scenario::Simulation& sim, int ticks) {
  std::vector<double> out;
  for (int i = 0; i < ticks; ++i) {
    sim.beginTick(std::nullopt);
    for (int k = 0; k < sim.stepsPerTick(); ++k) EXPECT_TRUE(sim.step().ok());
    const vehicle::VehicleSample s = sim.sample();
    out.insert(out.end(), {s.yawRate, s.ay, s.vx, static_cast<double>(sim.rung())});
  }
  return out;
}

struct Case {
  const char* scenario;
  const char* vehicle;
  bool automatic;
  double at;  // s into the run where the state is written
};

class RunStateBytes : public ::testing::TestWithParam<Case> {};

TEST_P(RunStateBytes, RestoredSimulationStepsBitForBitAsTheOriginal) {
  const Case c = GetParam();
  const scenario::ScenarioSpec sp = spec(c.scenario, c.vehicle, c.automatic);
  scenario::Simulation a(sp);
  {
    scenario::RunOptions o;
    o.sample = false;
    scenario::Run run(a, o);
    while (a.time() < c.at && run.tick(std::nullopt)) {
    }
  }
  const std::vector<char> bytes = a.saveBytes();
  const scenario::RunState state = scenario::runStateFromBytes(bytes);
  EXPECT_TRUE(state == a.save());
  EXPECT_EQ(scenario::runStateToBytes(state), bytes);
  EXPECT_EQ(scenario::hashRunState(state), scenario::hashRunState(a.save()));
  const std::vector<double> original = drive(a, 150);
  if (c.automatic) {  // the state was written or continued on the planar rung
    bool planar = a.save().rung == 1 || state.rung == 1;
    for (size_t i = 3; i < original.size(); i += 4) planar = planar || original[i] == 1.0;
    EXPECT_TRUE(planar);
  }
  EXPECT_NE(scenario::hashRunState(a.save()), scenario::hashRunState(state));  // it moved on

  // A second simulation of the same scenario, prepared from scratch, then
  // put where the first one was.
  scenario::Simulation b(sp);
  b.prepare();
  b.restoreBytes(bytes);
  EXPECT_EQ(drive(b, 150), original);
  EXPECT_TRUE(b.save() == a.save());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RunStateBytes,
    ::testing::Values(Case{"scenarios/jturn.toml", "vehicles/sedan.toml", false, 1.3},
                      Case{"scenarios/lane_change.toml", nullptr, true, 2.0},
                      Case{"scenarios/drive_powertrain.toml", nullptr, false, 1.0}),
    [](const auto& info) { return std::string(info.index == 0 ? "Linkage" : info.index == 1 ? "Auto" : "Powertrain"); });

// Every way the bytes can be wrong: the message says which, and the
// simulation keeps its state.
// The run state holds what carries from step to step, not the latest
// evaluation's outputs: a run sampled at every tick (telemetry) and one
// never sampled end in the same state, bit for bit, `auto`'s switches
// included (its policy reads the accepted step's tyre forces, not whatever
// a sample evaluated last).
TEST(RunStateBytes, SamplingDoesNotChangeTheRun) {
  const scenario::ScenarioSpec s = spec("scenarios/hard/curb_strike.toml", nullptr, true);
  scenario::Simulation sampled(s), quiet(s);
  sampled.prepare();
  quiet.prepare();
  for (int i = 0; i < 300; ++i) {
    for (scenario::Simulation* sim : {&sampled, &quiet}) {
      sim->beginTick(std::nullopt);
      for (int k = 0; k < sim->stepsPerTick(); ++k) ASSERT_TRUE(sim->step().ok());
    }
    sampled.sample();
  }
  EXPECT_GT(sampled.fidelitySwitches(), 0);
  EXPECT_EQ(scenario::hashRunState(sampled.save()), scenario::hashRunState(quiet.save()));
}

TEST(RunStateBytesErrors, RefusedWithWhatIsWrong) {
  scenario::Simulation sim(spec("scenarios/jturn.toml", "vehicles/sedan.toml"));
  sim.prepare();
  const std::vector<char> good = sim.saveBytes();
  const scenario::RunState before = sim.save();
  auto refused = [&](const std::vector<char>& bytes, const std::string& expected) {
    try {
      sim.restoreBytes(bytes);
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const scenario::RunStateBytesError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    EXPECT_TRUE(sim.save() == before);
  };
  refused({}, "not a bdfcar run state");
  refused(std::vector<char>(good.begin(), good.begin() + 5), "not a bdfcar run state");
  std::vector<char> b = good;
  b[0] = 'X';
  refused(b, "not a bdfcar run state");
  b = good;
  b[8] = 99;  // the format version's low byte
  refused(b, "format version 99");
  for (size_t cut : {good.size() - 1, good.size() / 2, size_t{30}}) refused(std::vector<char>(good.begin(), good.begin() + cut), "truncated or extended");
  b = good;
  b.push_back(0);
  refused(b, "truncated or extended");
  b = good;
  b[good.size() / 2] ^= 0x10;  // one bit inside the payload
  refused(b, "checksum");

  // Well-formed bytes of another vehicle's state (the paper's topology: other sizes).
  scenario::Simulation other(spec("scenarios/jturn.toml", "vehicles/paper.toml"));
  other.prepare();
  refused(other.saveBytes(), "another vehicle or rung");
  // Another car whose model has this one's sizes (both cars' planar rungs:
  // 12 coordinates, 3 rack drivers): refused by the models' fingerprint.
  scenario::ScenarioSpec planarSedan = spec("scenarios/jturn.toml", "vehicles/sedan.toml");
  scenario::ScenarioSpec planarPaper = spec("scenarios/jturn.toml", "vehicles/paper.toml");
  ASSERT_TRUE(scenario::parseFidelity("planar", planarSedan.fidelity));
  ASSERT_TRUE(scenario::parseFidelity("planar", planarPaper.fidelity));
  scenario::Simulation sedanPlanar(planarSedan), paperPlanar(planarPaper);
  sedanPlanar.prepare();
  paperPlanar.prepare();
  ASSERT_EQ(sedanPlanar.save().integrator.node(0).q.size(), paperPlanar.save().integrator.node(0).q.size());
  try {
    sedanPlanar.restoreBytes(paperPlanar.saveBytes());
    ADD_FAILURE() << "a planar paper car's state accepted by a planar sedan";
  } catch (const scenario::RunStateBytesError& e) {
    EXPECT_NE(std::string(e.what()).find("model fingerprint"), std::string::npos) << e.what();
  }
  // And a rung this simulation has not got.
  scenario::RunState s = before;
  s.rung = 3;
  refused(scenario::runStateToBytes(s), "rung 3");
}

}  // namespace
}  // namespace bdfcar
