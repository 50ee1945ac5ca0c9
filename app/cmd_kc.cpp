// `bdfcar kc VEHICLE.toml [--out DIR]`: the K&C rig (physics/vehicle/kc_rig.h):
// the linkage's standard kinematic numbers at design on stdout and, with
// --out, the sweeps' curves as CSV (degrees for angles) and PNG plots.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_errors.h"
#include "commands.h"
#include "kc_summary.h"
#include "config/units.h"
#include "scenario/row_file.h"
#include "session/plots.h"
#include "vehicle/kc_rig.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar::app {

namespace {

using config::radToDeg;

// A table's header name and output value for a column: angles in degrees.
std::string header(const vehicle::KcColumn& c) {
  if (c.unit == "rad") return c.name + "_deg";
  if (c.unit == "1") return c.name;
  if (c.unit == "m/m") return c.name + "_m_per_m";
  return c.name + "_" + c.unit;
}

void writeTable(const vehicle::KcTable& t, const std::filesystem::path& file) {
  std::ofstream f(file);
  for (size_t k = 0; k < t.columns.size(); ++k) f << (k ? "," : "") << header(t.columns[k]);
  f << "\n";
  char buf[32];
  for (size_t i = 0; i < t.columns[0].values.size(); ++i) {
    for (size_t k = 0; k < t.columns.size(); ++k) {
      const vehicle::KcColumn& c = t.columns[k];
      std::snprintf(buf, sizeof buf, "%.9g", c.unit == "rad" ? radToDeg(c.values[i]) : c.values[i]);
      f << (k ? "," : "") << buf;
    }
    f << "\n";
  }
  f.close();
  if (!f) throw scenario::OutputError("cannot write " + file.string());
}

// The curves' plots: each quantity over its sweep, per corner.
std::string plotTables(const std::filesystem::path& dir) {
  auto csv = [&](const char* name) { return (dir / (std::string(name) + ".csv")).string(); };
  auto png = [&](const char* name) { return (dir / (std::string(name) + ".png")).string(); };
  auto corners = [](const std::string& prefix, const std::string& suffix) {
    std::vector<std::string> out;
    for (const char* c : vehicle::kCornerNames) out.push_back(prefix + c + suffix);
    return out;
  };
  const std::vector<CsvPlot> plots = {
      {csv("parallel_travel"), png("bump_steer"), "toe (deg, + in) over parallel wheel travel", "travel_m",
       corners("toe_", "_deg")},
      {csv("parallel_travel"), png("camber_gain"), "camber (deg, + top out) over parallel wheel travel", "travel_m",
       corners("camber_", "_deg")},
      {csv("parallel_travel"), png("roll_centre"), "roll-centre height (m) over parallel wheel travel", "travel_m",
       {"roll_centre_front_m", "roll_centre_rear_m"}},
      {csv("roll"), png("roll_steer"), "toe (deg, + in) over body roll (+ left side up)", "roll_deg",
       corners("toe_", "_deg")},
      {csv("roll"), png("roll_camber"), "camber to the ground (deg) over body roll (+ left side up)", "roll_deg",
       corners("camber_to_ground_", "_deg")},
      {csv("steering"), png("steering"), "front road-wheel angles (deg, + left) over the steering-wheel angle",
       "steering_wheel_deg", {"steer_FL_deg", "steer_FR_deg", "ackermann_outer_deg"}},
  };
  return plotCsvColumns(plots, (dir / "plots.gp").string());
}

int runKc(const std::string& path, const std::string& out) {
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(path));
  const vehicle::KcResult r = vehicle::runKcRig(v);
  std::fputs(kcSummary(v, path, r).c_str(), stdout);
  if (out.empty()) return kExitOk;
  const std::filesystem::path dir(out);
  std::filesystem::create_directories(dir);
  for (const vehicle::KcTable& t : r.tables) writeTable(t, dir / (t.name + ".csv"));
  const std::string plots = plotTables(dir);
  std::printf("\ncurves: %s/{parallel_travel,roll,steering}.csv%s%s\n", out.c_str(),
              plots.empty() ? " and PNG plots" : "; ", plots.c_str());
  return kExitOk;
}

}  // namespace

void addKcCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "kc", "K&C rig (kinematics): sweep the linkage in parallel travel, roll and steer; print bump steer, camber "
            "gain, roll steer and camber, roll centres, caster, KPI, scrub, trail, wheel rates, motion ratios, "
            "anti-dive / anti-squat, steering ratio and Ackermann (docs/VEHICLES.md)");
  auto path = std::make_shared<std::string>();
  cmd->add_option("file", *path, "Vehicle file (assets/vehicles/*.toml) of a linkage vehicle")
      ->required()
      ->check(CLI::ExistingFile);
  auto out = std::make_shared<std::string>();
  cmd->add_option("--out", *out, "Directory for the curves: parallel_travel.csv, roll.csv, steering.csv and PNG plots");
  commands.push_back({cmd, [path, out] { return reportErrors([&] { return runKc(*path, *out); }); }});
}

}  // namespace bdfcar::app
