// RESULTS.md section: the reference sedan's vehicle sheet and its metrics in
// the shipped standard tests (assets/scenarios/standard/, docs/STANDARD_TESTS.md).
#include <filesystem>

#include "report/studies.h"
#include "scenario/limit_search.h"
#include "scenario/run_metrics.h"
#include "scenario/standard_tests.h"
#include "vehicle/vehicle_file.h"
#include "vehicle/vehicle_sheet.h"

namespace bdfcar::app {

void standardTestsSection(std::ostream& md, const std::string& vehicleFile) {
  const vehicle::Vehicle car = vehicle::buildVehicle(vehicle::loadVehicleFile(vehicleFile));
  const bool sedan = vehicleFile == asset("vehicles/sedan.toml");
  md << "## 5e. " << (sedan ? std::string("The reference sedan") : car.spec.name) << ": vehicle sheet and standard tests\n\n"
     << "`bdfcar info " << (sedan ? std::string("assets/vehicles/sedan.toml") : vehicleFile)
     << "` prints the sheet, derived from the linkage (no figure entered by hand"
     << (sedan ? "; the steering ratio is the reference data's: 30 deg of steering wheel at full input" : "")
     << "):\n\n```\n" << vehicle::describe(vehicle::vehicleSheet(car)) << "```\n\n"
     << "The shipped standard tests (definitions and sources: docs/STANDARD_TESTS.md), at the paper's setting"
     << (sedan ? "" : ", on this vehicle") << ":\n\n";
  for (const char* file : {"standard/iso7401_step_steer_80.toml", "standard/fmvss126_sine_with_dwell_80.toml",
                           "standard/iso4138_constant_steer.toml", "standard/iso4138_constant_radius_40m.toml",
                           "standard/iso3888_2_obstacle_avoidance_60.toml"}) {
    scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset(std::string("scenarios/") + file));
    if (!sedan) spec.vehicleFile = vehicleFile;
    scenario::Simulation sim(spec);
    const scenario::RunResult r = scenario::runScenario(sim, {});
    if (!r.ok) {
      md << "`" << file << "`: the run failed: " << r.failure << "\n\n";
      continue;
    }
    if (r.course) {
      // A course: its verdict and speeds (run_metrics.h).
      md << "`" << file << "`:\n\n| metric | value |\n|---|---|\n";
      for (const scenario::Metric& m : scenario::runMetrics(r))
        if (m.name.rfind("course_", 0) == 0 || m.name == "cones_hit") md << "| " << m.name << " | " << m.value << " |\n";
      md << "\n";
      command(md, std::string("assets/scenarios/") + file + (sedan ? "" : " --vehicle " + vehicleFile) +
                      " --metrics metrics.csv");
      continue;
    }
    const scenario::StandardTestReport report = scenario::standardTestReport(
        spec.standardTest, scenario::timeHistory(r, sim.vehicle()));
    md << "```\n" << report.text << "```\n\n";
    command(md, std::string("assets/scenarios/") + file + (sedan ? "" : " --vehicle " + vehicleFile) +
                    " --metrics metrics.json");
  }
  // The highest passing speeds through the courses, each driver (bdfcar limit).
  md << "The highest passing entry speed through each course (`bdfcar limit`, 30-100 km/h to 0.5 km/h; no corner "
        "out of a lane, no cone down), the look-ahead follower against the preview driver:\n\n"
        "| course | pure pursuit | preview driver |\n|---|---|---|\n";
  for (const char* file : {"iso_lane_change.toml", "standard/iso3888_2_obstacle_avoidance_60.toml"}) {
    scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset(std::string("scenarios/") + file));
    if (!sedan) spec.vehicleFile = vehicleFile;
    md << "| `" << file << "` |";
    for (auto law : {scenario::PathFollowerSpec::Law::PurePursuit, scenario::PathFollowerSpec::Law::Preview}) {
      spec.pathFollower.law = law;
      scenario::LimitSearchSpec ls;
      ls.jobs = 2;
      md << " " << scenario::searchLimit(ls, [&](double v) { return scenario::courseTrial(spec, v); }).describe() << " |";
    }
    md << "\n";
  }
  md << "\n";
  md << "Command: `bdfcar limit assets/scenarios/standard/iso3888_2_obstacle_avoidance_60.toml --driver preview"
     << (sedan ? "" : " --vehicle " + vehicleFile) << "` (and without `--driver`, and on iso_lane_change.toml)\n\n";
}

}  // namespace bdfcar::app
