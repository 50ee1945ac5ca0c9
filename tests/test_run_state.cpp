// The run state as one value and the driver's tick: save / restore repeats a
// run bit for bit, a rewind goes back to a snapshot and repeats what followed
// it, the driver's tick is independent of the integration step, and a
// divergence in a rewindable run goes back to the last good snapshot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "scenario/run.h"
#include "scenario/simulation.h"

#include "test_files.h"

using namespace bdfcar;

namespace {

using test::asset;
using test::readFile;
std::string temp(const std::string& name) { return test::tempFile("runstate", name); }

// A person's input at tick i: weaving, throttle, then brakes.
scenario::DriverInput personAt(int i) {
  const double t = 0.01 * i;
  return {0.3 * std::sin(2.0 * t) + 0.05 * std::sin(37.0 * t), t < 1.5 ? 0.6 : 0.0, t > 2.2 ? 0.4 : 0.0};
}

// Telemetry rows of `ticks` driver ticks from the current state, as CSV text.
std::string driveTicks(scenario::Simulation& sim, int first, int ticks, const std::string& file) {
  {
    scenario::TelemetryWriter w(file, sim.vehicle());
    for (int i = first; i < first + ticks; ++i) {
      sim.beginTick(personAt(i));
      for (int k = 0; k < sim.stepsPerTick(); ++k) EXPECT_TRUE(sim.step().ok());
      w.write(sim.sample(), {sim.steerAt(sim.time()), 0, 0, 0, 0, 0, 0, 0.0, {}, {}});
    }
  }
  return readFile(file);
}

// A run that keeps no samples in memory; rewindable or only restartable.
scenario::RunOptions runOptions(bool rewindable) {
  scenario::RunOptions o;
  o.keepSamples = false;
  o.rewindable = rewindable;
  o.restartable = true;
  return o;
}

}  // namespace

TEST(RunState, SaveStep200RestoreStep200IsBitIdentical) {
  scenario::Simulation sim(scenario::loadScenarioFile(asset("scenarios/drive.toml")));
  sim.prepare();
  driveTicks(sim, 0, 50, temp("warmup.csv"));  // away from the start, mid-manoeuvre
  const scenario::RunState saved = sim.save();
  const std::string first = driveTicks(sim, 50, 200, temp("a.csv"));
  const scenario::RunState after = sim.save();
  EXPECT_FALSE(after == saved) << "the state moved on";
  sim.restore(saved);
  const std::string second = driveTicks(sim, 50, 200, temp("b.csv"));
  EXPECT_GT(first.size(), 20000u);
  EXPECT_EQ(first, second) << "the restored run differs";
  EXPECT_TRUE(sim.save() == after) << "and so does its final state";
}

TEST(RunState, ACopiedStateComparesEqualAndADifferentOneDoesNot) {
  scenario::Simulation sim(scenario::loadScenarioFile(asset("scenarios/jturn.toml")));
  sim.prepare();
  const scenario::RunState a = sim.save();
  scenario::RunState b = a;
  EXPECT_TRUE(a == b);
  b.integrator.node(0).v(0) = std::nextafter(b.integrator.node(0).v(0), 1e9);
  EXPECT_FALSE(a == b) << "one ulp of one velocity";
  b = a;
  b.forces.wheels[2].brakeDeflection += 1e-12;
  EXPECT_FALSE(a == b) << "a force-law state";
}

TEST(Tick, ADriverTickRunsTickOverStepStepsWhateverTheStep) {
  // 300 ticks of a person's input end at 3 s of simulated time with 10, 5
  // and 2.5 ms steps, and the runs agree with each other (the same car, the
  // same driver, a finer step).
  double yFinal[3] = {};
  const double steps[3] = {0.01, 0.005, 0.0025};
  for (int k = 0; k < 3; ++k) {
    scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
    spec.integrator.step = steps[k];
    scenario::Simulation sim(spec);
    scenario::Run run(sim, runOptions(false));
    ASSERT_FALSE(run.failed()) << run.failure();
    EXPECT_EQ(sim.stepsPerTick(), std::lround(0.01 / steps[k]));
    for (int i = 0; i < 300; ++i) ASSERT_TRUE(run.tick(personAt(i))) << run.failureText();
    EXPECT_NEAR(run.time(), 3.0, 1e-9) << "step " << steps[k];
    EXPECT_EQ(run.steps(), 300 * sim.stepsPerTick());
    yFinal[k] = run.lastSample().com.y();
    EXPECT_GT(std::abs(yFinal[k] - spec.startY), 0.5) << "the car weaved";
  }
  // The same drive: the lateral position after 3 s of weaving agrees to
  // millimetres across the steps (it moves by metres).
  EXPECT_NEAR(yFinal[0], yFinal[2], 0.005) << "m";
  EXPECT_NEAR(yFinal[1], yFinal[2], 0.005) << "m";
}

TEST(Tick, AStepThatDoesNotDivideTheTickIsRefused) {
  EXPECT_EQ(scenario::stepsPerTick(0.01, 0.0025), 4);
  EXPECT_EQ(scenario::stepsPerTick(0.01, 0.01), 1);
  EXPECT_EQ(scenario::stepsPerTick(0.01, 0.003), 0);
  EXPECT_EQ(scenario::stepsPerTick(0.01, 0.02), 0);
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  spec.integrator.step = 0.003;
  try {
    scenario::Simulation sim(spec);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("does not divide the driver's tick"), std::string::npos) << e.what();
  }
  // In a file: the key and its line.
  const std::string bad = temp("bad_step.toml");
  std::ofstream(bad) << "[scenario]\nname = \"x\"\nvehicle = \"" << asset("vehicles/sedan.toml")
                     << "\"\nduration = \"1 s\"\n[integrator]\nstep = \"3 ms\"\n";
  try {
    scenario::loadScenarioFile(bad);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("bad_step.toml:6"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("divides the driver's tick"), std::string::npos) << e.what();
  }
}

TEST(Rewind, GoingBackASnapshotRepeatsWhatFollowedIt) {
  scenario::Simulation sim(scenario::loadScenarioFile(asset("scenarios/drive.toml")));
  scenario::Run run(sim, runOptions(true));
  for (int i = 0; i < 130; ++i) ASSERT_TRUE(run.tick(personAt(i)));
  const vehicle::VehicleSample original = run.lastSample();
  const scenario::RunState stateAt130 = sim.save();
  ASSERT_TRUE(run.rewind());
  EXPECT_EQ(run.ticks(), 100) << "snapshots every 0.5 s: back to tick 100";
  EXPECT_NEAR(run.time(), 1.0, 1e-9);
  for (int i = 100; i < 130; ++i) ASSERT_TRUE(run.tick(personAt(i)));
  EXPECT_EQ(std::memcmp(&run.lastSample().com, &original.com, sizeof original.com), 0);
  EXPECT_EQ(run.lastSample().yawRate, original.yawRate);
  EXPECT_TRUE(sim.save().integrator.sameHistory(stateAt130.integrator));
  // Back again within a second of driving since the last rewind: on from
  // where that one landed (1.0 s), to 0.5 s; then the start, then nothing.
  ASSERT_TRUE(run.rewind());
  EXPECT_NEAR(run.time(), 0.5, 1e-9);
  ASSERT_TRUE(run.rewind());
  EXPECT_NEAR(run.time(), 0.0, 1e-9);
  EXPECT_FALSE(run.rewind());
}

TEST(Rewind, RestartIsAnAssignmentOfTheInitialState) {
  scenario::Simulation sim(scenario::loadScenarioFile(asset("scenarios/drive.toml")));
  scenario::Run run(sim, runOptions(false));
  const vehicle::VehicleSample start = run.lastSample();
  for (int i = 0; i < 80; ++i) ASSERT_TRUE(run.tick(personAt(i)));
  run.restart();
  EXPECT_EQ(run.ticks(), 0);
  EXPECT_EQ(sim.time(), start.t);
  EXPECT_EQ(sim.sample().com.x(), start.com.x());
}

// A car that overturns in a drive (tests/data/bad/scenario_overturns.toml:
// the centre of mass 0.9 m up, a fishhook at 120 km/h) goes back to a
// snapshot with the check's own reason on the HUD's line, where `run` ends
// with it; no row of the overturned car is recorded.
TEST(Rewind, AnOverturnedCarGoesBackSayingSo) {
  const std::vector<config::Setting> high{config::parseSetting("vehicle.bodies[0].com=[0.056,0.0,0.9]")};
  scenario::ScenarioSpec spec =
      scenario::loadScenarioFile(std::string(BDFCAR_SOURCE_DIR) + "/tests/data/bad/scenario_overturns.toml", high);
  scenario::Simulation sim(spec);
  scenario::RunOptions o = runOptions(true);
  o.sample = true;
  double lowestRoof = 1e9;
  o.onSample = [&](const vehicle::VehicleSample& s) { lowestRoof = std::min(lowestRoof, s.chassisRotation(2, 2)); };
  scenario::Run run(sim, o);
  for (int i = 0; i < 400 && run.resets() == 0; ++i) ASSERT_TRUE(run.tick(std::nullopt));
  ASSERT_GT(run.resets(), 0) << "the car did not overturn";
  EXPECT_EQ(run.notice().rfind("the car overturned at t = ", 0), 0u) << run.notice();
  EXPECT_NE(run.notice().find(": back to t = "), std::string::npos) << run.notice();
  EXPECT_GE(lowestRoof, 0.0) << "a row of the car upside down was recorded";
}

TEST(Rewind, ADivergenceGoesBackToTheLastGoodSnapshotInsteadOfEndingTheRun) {
  // Semi-implicit Euler at 10 ms diverges on this car (docs/RESULTS.md 4);
  // a rewindable run absorbs each divergence and keeps going.
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  spec.integrator.method = scenario::IntegratorMethod::SemiImplicitEuler;
  spec.settleTime = 0;
  scenario::Simulation sim(spec);
  scenario::Run run(sim, runOptions(true));
  ASSERT_FALSE(run.failed()) << run.failure();
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(run.tick(personAt(i)));
  EXPECT_FALSE(run.failed());
  EXPECT_GT(run.resets(), 0);
  EXPECT_NE(run.notice().find("back to t = "), std::string::npos) << run.notice();
  EXPECT_TRUE(sim.save().integrator.node(0).q.allFinite());
  // The same scenario without rewind ends with the one failure text.
  scenario::Simulation sim2(spec);
  scenario::Run plain(sim2, {});
  while (!plain.finished() && plain.tick(personAt(0))) {
  }
  ASSERT_TRUE(plain.failed());
  EXPECT_NE(plain.failureText().find("the run failed at t = "), std::string::npos) << plain.failureText();
}

TEST(SteeringSystem, FullLeftFullRightEveryTickAt80IsAHardInputNotATear) {
  // The flip-flop that used to diverge ("non-finite equations of motion"):
  // the rack follows through the steering system, bounded in speed.
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  spec.initialSpeed = 80 / 3.6;
  scenario::Simulation sim(spec);
  scenario::Run run(sim, runOptions(false));
  ASSERT_FALSE(run.failed()) << run.failure();
  const double vmax = sim.vehicle().spec.steering.maxRackSpeed;
  double rack = sim.sample().rack, maxRate = 0;
  for (int i = 0; i < 500; ++i) {
    ASSERT_TRUE(run.tick(scenario::DriverInput{i % 2 ? 1.0 : -1.0, 0.0, 0.0})) << run.failureText();
    const double r = sim.sample().rack;
    maxRate = std::max(maxRate, std::abs(r - rack) / spec.tick);
    rack = r;
  }
  EXPECT_LE(maxRate, vmax * (1 + 1e-9)) << "m/s";
  // No throttle: the car can only lose speed, and it is still rolling.
  EXPECT_LT(run.lastSample().speed, spec.initialSpeed + 0.05);
  EXPECT_GT(run.lastSample().speed, 5.0);
}

TEST(SteeringSystem, AStepCommandReachesTheRackWithinTheLimits) {
  // Analytic: from rest, a full-lock step: the rack accelerates at the
  // limit, runs at the maximum speed, and settles on the command.
  const scenario::SteeringLimits l{0.03, 2.0, 60.0};
  double s = 0, r = 0, peak = 0;
  const double tick = 0.01;
  for (int i = 0; i < 200; ++i) {
    const double a = scenario::steeringAcceleration(l, s, r, 1.0, tick);
    EXPECT_LE(std::abs(a), l.maxAcceleration * (1 + 1e-12));
    s += (r + 0.5 * a * tick) * tick;
    r += a * tick;
    EXPECT_LE(std::abs(r), l.maxRate * (1 + 1e-12));
    peak = std::max(peak, s);
    if (i == 2) {
      EXPECT_NEAR(r, 3 * tick * l.maxAcceleration, 1e-12) << "acceleration-limited start";
    }
  }
  EXPECT_NEAR(s, 1.0, 1e-6) << "settles on the command";
  EXPECT_LT(peak, 1.02) << "without a large overshoot";
  // Full travel at 2 /s takes at least 0.5 s: not reached before.
  double s2 = 0, r2 = 0;
  for (int i = 0; i < 45; ++i) {
    const double a = scenario::steeringAcceleration(l, s2, r2, 1.0, tick);
    s2 += (r2 + 0.5 * a * tick) * tick;
    r2 += a * tick;
  }
  EXPECT_LT(s2, 0.9);
}

TEST(SteeringSystem, AScriptedSteeringThatDoesNotStartAtZeroIsRampedInDuringSettling) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/jturn.toml"));
  spec.steering.kind = scenario::SignalSpec::Kind::Constant;
  spec.steering.level = 0.5;
  scenario::Simulation sim(spec);
  const scenario::RunResult r = scenario::runScenario(sim, runOptions(false));
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_NEAR(sim.steerAt(0.0), 0.5, 1e-12);
  EXPECT_NEAR(sim.steerAt(-spec.settleTime + 1e-9), 0.0, 1e-6) << "from the design position";
}

// The telemetry writer formats rows on a thread of its own: a burst of rows
// far faster than it can format (a full queue) loses none and keeps their
// order, and flush() hands every queued row to the file.
TEST(RunState, TelemetryBurstKeepsEveryRowInOrder) {
  scenario::Simulation sim(scenario::loadScenarioFile(asset("scenarios/jturn.toml")));
  sim.prepare();
  const vehicle::VehicleSample base = sim.sample();
  const std::string file = temp("burst.csv");
  std::filesystem::remove(file);  // an earlier run's complete file must not stand in for this one's rows
  const int rows = 5000;  // about five times the writer's queue
  scenario::TelemetryWriter w(file, sim.vehicle());
  for (int i = 0; i < rows; ++i) {
    vehicle::VehicleSample s = base;
    s.t = i;  // an integer: printed exactly
    w.write(s, {});
  }
  w.flush();
  // Until close() the rows are in PATH.partial (row_file.h).
  std::istringstream text(readFile(scenario::RowFile::partialPath(file)));
  std::string line;
  std::getline(text, line);
  EXPECT_EQ(line, scenario::TelemetryWriter::header());
  int n = 0;
  while (std::getline(text, line)) {
    ASSERT_EQ(line.substr(0, line.find(',')), std::to_string(n)) << "row " << n;
    ++n;
  }
  EXPECT_EQ(n, rows);
  w.close();
  std::filesystem::remove(file);
}

// docs/TELEMETRY.md documents every column of the header (quantity, unit,
// sign and frame): a column added to the writer but not to the document
// fails here.
TEST(Telemetry, EveryColumnIsDocumented) {
  const std::string doc = readFile(std::string(BDFCAR_SOURCE_DIR) + "/docs/TELEMETRY.md");
  ASSERT_FALSE(doc.empty()) << "docs/TELEMETRY.md";
  // The first cell of each table row, split at commas: the documented names.
  std::set<std::string> documented;
  std::istringstream lines(doc);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| ", 0) != 0) continue;
    std::istringstream cell(line.substr(2, line.find(" |", 2) - 2));
    for (std::string name; std::getline(cell, name, ',');) {
      name.erase(0, name.find_first_not_of(' '));
      documented.insert(name);
    }
  }
  std::istringstream header(std::string(scenario::TelemetryWriter::header()) + "," +
                            scenario::TelemetryWriter::powertrainHeader() + "," + scenario::TelemetryRowMaker::lapHeader());
  int columns = 0;
  for (std::string column; std::getline(header, column, ','); ++columns)
    EXPECT_TRUE(documented.count(column)) << "column '" << column << "' is not in docs/TELEMETRY.md";
  EXPECT_GE(columns, 50);
}

// The per-step cost's ranks by selection against the sorted list they are
// defined on (a second algorithm): odd and even lengths, ties, one step.
TEST(StepCost, RanksBySelectionAreTheSortedListsRanks) {
  std::vector<std::vector<float>> cases = {{3e-6f}, {2e-6f, 1e-6f}, {5e-6f, 5e-6f, 1e-6f, 9e-6f, 5e-6f}};
  std::vector<float> many;
  unsigned state = 12345;
  for (int i = 0; i < 1001; ++i) {
    state = state * 1103515245u + 12345u;
    many.push_back(1e-6f * static_cast<float>((state >> 16) % 97));  // ties by the dozen
  }
  cases.push_back(many);
  many.pop_back();
  cases.push_back(many);
  for (const std::vector<float>& c : cases) {
    std::vector<float> sorted = c;
    std::sort(sorted.begin(), sorted.end());
    auto at = [&](double q) { return 1e6 * sorted[std::min(sorted.size() - 1, static_cast<size_t>(q * (sorted.size() - 1) + 0.5))]; };
    const scenario::StepCost cost = scenario::stepCost(c);
    EXPECT_EQ(cost.p50, at(0.5)) << c.size() << " steps";
    EXPECT_EQ(cost.p99, at(0.99)) << c.size() << " steps";
    EXPECT_EQ(cost.max, 1e6 * sorted.back()) << c.size() << " steps";
  }
}
