// Inputs an engineer writes (docs/SCENARIOS.md): steering as steering-wheel
// angle, road-wheel angle or rack travel gives the run of the same input
// normalised; a CSV file of inputs (a run's own telemetry) replays the run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "vehicle/motion_ratio.h"
#include "vehicle/vehicle_file.h"

using namespace bdfcar;
namespace fs = std::filesystem;

namespace {

const std::string kJTurn = std::string(BDFCAR_SOURCE_DIR) + "/assets/scenarios/jturn.toml";
const std::string kLaneChange = std::string(BDFCAR_SOURCE_DIR) + "/assets/scenarios/lane_change.toml";

std::vector<vehicle::VehicleSample> run(const std::string& file, const std::vector<std::string>& settings,
                                        const std::string& telemetry = "") {
  std::vector<config::Setting> s;
  for (const std::string& x : settings) s.push_back(config::parseSetting(x));
  scenario::Simulation sim(scenario::loadScenarioFile(file, s));
  scenario::RunOptions o;
  o.telemetryPath = telemetry;
  const scenario::RunResult r = scenario::runScenario(sim, o);
  EXPECT_TRUE(r.ok) << r.failure;
  return r.samples;
}

double maxDifference(const std::vector<vehicle::VehicleSample>& a, const std::vector<vehicle::VehicleSample>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::abs(a[i].yawRate - b[i].yawRate));
  return d;
}

}  // namespace

// The J-turn's 0.2 of full steering, written in each unit: the vehicle's
// 30 deg of steering wheel and 52.36 mm of rack at full input, and the
// linkage's road-wheel angle per unit input. The runs agree to rounding.
TEST(SteeringInputs, EngineeringUnitsGiveTheNormalisedRun) {
  const std::vector<vehicle::VehicleSample> base = run(kJTurn, {});
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(kJTurn);
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(spec.vehicleFile));
  const double roadWheelDeg = 0.2 * vehicle::roadWheelAnglePerSteer(v) * 180 / M_PI;
  char road[64];
  std::snprintf(road, sizeof road, "steering.level=\"%.17g deg\"", roadWheelDeg);
  for (const std::vector<std::string>& s : std::vector<std::vector<std::string>>{
           {"steering.unit=steering_wheel_angle", "steering.level=\"6 deg\""},
           {"steering.unit=rack_travel", "steering.level=0.01047198"},
           {"steering.unit=road_wheel_angle", road}}) {
    const double d = maxDifference(base, run(kJTurn, s));
    std::printf("%s: largest yaw-rate difference %.3g rad/s\n", s[0].c_str(), d);
    EXPECT_LT(d, 1e-6) << s[0];  // the rack's 0.0523599 m is written to 7 digits
  }
  EXPECT_GT(roadWheelDeg, 2.0);  // about 2.9 deg at the road wheels for 6 deg of steering wheel
  EXPECT_LT(roadWheelDeg, 4.0);
  // Beyond the vehicle's full steering: refused, at the steering table.
  try {
    run(kJTurn, {"steering.unit=steering_wheel_angle", "steering.level=\"45 deg\""});
    ADD_FAILURE() << "45 deg of a 30 deg steering wheel accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the vehicle's full steering (30 deg)"), std::string::npos) << e.what();
  }
}

// A run's telemetry as a CSV input file (its steer_in column, linear between
// the 10 ms rows) replays the run: the lane change's yaw rate within 0.5 % of
// its peak (linear between the rows, the prescribed rack moves at piecewise
// constant speed; 0.24 % measured).
TEST(SteeringInputs, ACsvFileOfARunsInputsReplaysIt) {
  const fs::path telemetry = fs::temp_directory_path() / "bdfcar_steering_csv.csv";
  const std::vector<vehicle::VehicleSample> a = run(kLaneChange, {}, telemetry.string());
  // The lane change with its [steering] table replaced by the CSV file.
  std::ifstream in(kLaneChange);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t from = text.find("[steering]"), to = text.find("\n\n", from);
  ASSERT_NE(from, std::string::npos);
  text.replace(from, to - from, "[steering]\ntype = \"csv\"\nfile = \"" + telemetry.string() + "\"");
  const std::string assets = std::string(BDFCAR_SOURCE_DIR) + "/assets/";
  for (size_t at; (at = text.find("\"../")) != std::string::npos;) text.replace(at, 4, "\"" + assets);
  const fs::path replay = fs::temp_directory_path() / "bdfcar_steering_csv.toml";
  std::ofstream(replay) << text;
  const std::vector<vehicle::VehicleSample> b = run(replay.string(), {});
  double peak = 0;
  for (const auto& s : a) peak = std::max(peak, std::abs(s.yawRate));
  const double e = maxDifference(a, b) / peak;
  std::printf("replayed from the CSV: largest yaw-rate difference %.4f %% of peak\n", 100 * e);
  EXPECT_LT(e, 0.005);
}
