// `bdfcar limit SCENARIO.toml [--from 30 --to 100 --resolution 0.5] [--jobs N] [--out DIR]`:
// the highest entry speed at which a course scenario passes (ISO 3888-2's
// figure), each trial a whole run of the scenario at that speed
// (scenario/limit_search.h), the runs at the highest passing and the first
// failing speed written to DIR with their plots.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <thread>

#include "cli_errors.h"
#include "commands.h"
#include "scenario/course_judge.h"
#include "scenario/limit_search.h"
#include "scenario/row_file.h"
#include "scenario/run.h"
#include "scenario_overrides.h"
#include "session/plots.h"

namespace bdfcar::app {

namespace {

int runLimit(const std::string& path, double from, double to, double resolution, int jobs, const std::string& out,
             const ScenarioOverrides& ov) {
  const scenario::ScenarioSpec base = loadScenario(path, ov);
  if (!base.course.iso3888)
    throw std::runtime_error(path + ": limit searches the speed through a course; the scenario has no [course]");
  if (!base.pathFollower.enabled)
    throw std::runtime_error(path + ": limit needs a path-following [driver] to steer through the course");
  if (!(to > from)) throw std::runtime_error("--to must be above --from");
  scenario::LimitSearchSpec s;
  s.from = from / 3.6;
  s.to = to / 3.6;
  s.resolution = resolution / 3.6;
  s.jobs = jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("%s: searching %.1f-%.1f km/h to %.1f km/h, %d trial%s at a time\n", base.name.c_str(), from, to,
              resolution, s.jobs, s.jobs == 1 ? "" : "s");
  std::fflush(stdout);
  std::mutex print;
  const scenario::LimitResult r = scenario::searchLimit(s, [&](double v) {
    scenario::LimitTrial t = scenario::courseTrial(base, v);
    const std::lock_guard<std::mutex> lock(print);
    std::printf("  %6.2f km/h: %s\n", v * 3.6, t.verdict.c_str());
    std::fflush(stdout);
    return t;
  });
  std::printf("%s\n", r.describe().c_str());
  if (!out.empty()) {
    // The two runs that bound the limit, again with their telemetry (the runs are deterministic).
    std::filesystem::create_directories(out);
    auto keep = [&](const char* what, double v) {
      char name[64];
      std::snprintf(name, sizeof name, "%s_%.2f_kmh", what, v * 3.6);
      const std::filesystem::path dir = std::filesystem::path(out) / name;
      std::filesystem::create_directories(dir);
      const std::string csv = (dir / "telemetry.csv").string();
      scenario::courseTrial(base, v, csv);
      const scenario::ScenarioSpec spec = scenario::courseScenarioAt(base, v);
      scenario::Simulation sim(spec);  // its course, sized to the car
      const std::string why = plotDrive(csv, dir.string(), sim.course(), spec.name + " at " + name);
      std::printf("%s: %s%s\n", what, dir.string().c_str(), why.empty() ? "" : (" (no plots: " + why + ")").c_str());
    };
    if (r.anyPass) keep("pass", r.highestPass);
    if (!r.allPass) keep("fail", r.anyPass ? r.lowestFail : s.from);
  }
  return r.anyPass ? kExitOk : kExitCourseFailed;
}

}  // namespace

void addLimitCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "limit", "Find the highest entry speed at which a course scenario passes (ISO 3888-2: no cone down)");
  auto path = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto from = std::make_shared<double>(30.0), to = std::make_shared<double>(100.0);
  auto resolution = std::make_shared<double>(0.5);
  auto jobs = std::make_shared<int>(0);
  auto ov = std::make_shared<ScenarioOverrides>();
  cmd->add_option("scenario", *path, "Scenario file with a [course] and a path-following [driver]")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--from", *from, "Lowest entry speed, km/h")->check(CLI::Range(1.0, 400.0));
  cmd->add_option("--to", *to, "Highest entry speed, km/h")->check(CLI::Range(1.0, 400.0));
  cmd->add_option("--resolution", *resolution, "Search until the bracket is this narrow, km/h")
      ->check(CLI::Range(0.01, 100.0));
  cmd->add_option("--jobs,-j", *jobs, "Trials run at once (default: the machine's cores)")->check(CLI::Range(0, 256));
  cmd->add_option("--out,-o", *out,
                  "Folder for the runs at the highest passing and the first failing speed (telemetry and plots)");
  addOverrideOptions(*cmd, *ov);
  commands.push_back({cmd, [=] {
                        return reportErrors([&] { return runLimit(*path, *from, *to, *resolution, *jobs, *out, *ov); });
                      }});
}

}  // namespace bdfcar::app
