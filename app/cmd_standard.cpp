// `bdfcar standard VEHICLE.toml [--out DIR] [--jobs N]`: every standard test
// on a vehicle with its amplitudes calibrated as the standards prescribe
// (scenario/calibration.h), the shipped scenarios (assets/scenarios/standard/)
// as the tests' settings:
//  - ISO 7401 step steer at 80 km/h, its step sized for 4 m/s^2 steady;
//  - FMVSS 126: the slowly increasing steer at 80 km/h and A at 0.3 g, then
//    the sine-with-dwell series from 1.5 A, both directions, and the verdict;
//  - ISO 4138 constant steering-wheel angle, the steering set for a 40 m
//    circle at 20 km/h: understeer gradient, characteristic or critical speed;
//  - ISO 3888-2: the highest passing entry speed with the preview driver.
// Prints a sheet (markdown) and writes it, with the runs' telemetry, to DIR.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "cli_errors.h"
#include "progress_bar.h"
#include "commands.h"
#include "report/studies.h"
#include "scenario/calibration.h"
#include "scenario/limit_search.h"
#include "scenario/parallel_runs.h"
#include "scenario/row_file.h"
#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "scenario/standard_tests.h"
#include "session/plots.h"

namespace bdfcar::app {

namespace {

constexpr double kG = 9.80665;

struct Setup {
  std::string vehicleFile, outDir;
  int jobs = 1;
};

scenario::ScenarioSpec shipped(const char* file, const Setup& s) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset(std::string("scenarios/standard/") + file));
  spec.vehicleFile = s.vehicleFile;
  return spec;
}

struct Ran {
  scenario::RunResult result;
  scenario::TimeHistory history;
};

Ran run(const scenario::ScenarioSpec& spec, const std::string& telemetry = "") {
  scenario::Simulation sim(spec);
  scenario::RunOptions opt;
  opt.telemetryPath = telemetry;
  Ran r{scenario::runScenario(sim, opt), {}};
  if (!r.result.ok) throw std::runtime_error(spec.name + ": the run failed: " + r.result.failure);
  r.history = scenario::timeHistory(r.result, sim.vehicle());
  return r;
}

std::string telemetryFile(const Setup& s, const std::string& name) {
  return s.outDir.empty() ? std::string() : (std::filesystem::path(s.outDir) / (name + ".csv")).string();
}

std::string png(const Setup& s, const std::string& name) {
  return (std::filesystem::path(s.outDir) / (name + ".png")).string();
}

// A plot of the runs' telemetry beside the sheet, named in it.
void plot(std::ostream& md, const CsvPlot& p) {
  const std::string why = plotCsvColumns({p}, p.png + ".gp");
  md << (why.empty() ? "Plot: " + std::filesystem::path(p.png).filename().string() : "(no plot: " + why + ")")
     << "\n\n";
}

void progress(const char* what) {
  std::fprintf(stderr, "standard: %s\n", what);
  std::fflush(stderr);
}

// ISO 7401: the step that gives 4 m/s^2 of steady lateral acceleration.
void iso7401(std::ostream& md, const Setup& s) {
  progress("ISO 7401 step steer: calibrating the step for 4 m/s^2");
  scenario::ScenarioSpec spec = shipped("iso7401_step_steer_80.toml", s);
  auto steady = [&](double level) {
    scenario::ScenarioSpec t = spec;
    t.steering.level = level;
    return scenario::iso7401StepSteer(run(t).history).ay.steady;
  };
  const scenario::Calibration c = scenario::calibrate(steady, 4.0, spec.steering.level, 0.005);
  spec.steering.level = c.input;
  const Ran r = run(spec, telemetryFile(s, "iso7401_step_steer"));
  const scenario::StepSteerMetrics m = scenario::iso7401StepSteer(r.history);
  md << "## ISO 7401 step steer, 80 km/h\n\nCalibrated: the step of " << m.steerStep
     << " deg of steering wheel gives " << m.ay.steady << " m/s^2 steady (asked 4 m/s^2, " << c.tries.size()
     << " runs" << (c.converged ? "" : "; NOT within 0.5 %: the car cannot reach it") << ").\n\n```\n"
     << scenario::describe(m) << "```\n\n";
  if (!s.outDir.empty())
    plot(md, {telemetryFile(s, "iso7401_step_steer"), png(s, "iso7401_step_steer"),
              "ISO 7401 step steer: yaw rate (rad/s) and lateral acceleration (m/s^2)", "time_s",
              {"yawrate_radps", "ay_mps2"}});
}

// FMVSS 126: A from the slowly increasing steer, then the series.
void fmvss126(std::ostream& md, const Setup& s) {
  progress("FMVSS 126: slowly increasing steer at 80 km/h");
  const scenario::ScenarioSpec base = shipped("fmvss126_sine_with_dwell_80.toml", s);
  const double full = scenario::Simulation(base).vehicle().spec.steering.steeringWheelFull * 180 / M_PI;  // deg at input 1
  scenario::ScenarioSpec sis = base;
  sis.name = "FMVSS 126 slowly increasing steer, 80 km/h";
  sis.standardTest = scenario::StandardTest::None;
  sis.steering = {};
  sis.steering.kind = scenario::SignalSpec::Kind::Ramp;
  sis.steering.start = 1.0;
  sis.steering.level = 1.0;
  sis.steering.duration = full / 13.5;  // 13.5 deg/s of steering wheel (S7.6.1)
  sis.steering.asDriverCommand = true;
  sis.duration = 1.0 + sis.steering.duration;
  sis.speedControl.enabled = true;
  sis.speedControl.profile = {};
  sis.speedControl.profile.target = 80 / 3.6;
  const Ran r = run(sis, telemetryFile(s, "fmvss126_sis"));
  const double A = scenario::sisAngleAt(r.history);
  md << "## FMVSS 126 sine with dwell, 80 km/h\n\n";
  if (!std::isfinite(A)) {
    md << "The slowly increasing steer never reached the regression window (0.1-0.375 g) with the steering at "
          "full: no A, no series.\n\n";
    return;
  }
  std::vector<double> amplitudes = scenario::fmvss126Amplitudes(A);
  // The car cannot steer beyond its full input: the series ends with the
  // first amplitude at or above it, run at it.
  const size_t all = amplitudes.size();
  for (size_t i = 0; i < amplitudes.size(); ++i)
    if (amplitudes[i] >= full) {
      amplitudes.resize(i + 1);
      amplitudes.back() = full;
      break;
    }
  md << "A = " << A << " deg of steering wheel at 0.3 g (S7.6, least squares over 0.1-0.375 g of the 13.5 deg/s "
     << "steer). The series (S7.9): " << amplitudes.size() << " amplitudes from " << amplitudes.front() << " to "
     << amplitudes.back() << " deg, each turning left first and right first";
  if (amplitudes.size() < all)
    md << "; the rule's series goes on to " << scenario::fmvss126Amplitudes(A).back()
       << " deg, beyond the car's full steering (" << full << " deg): it ends there";
  md << ".\n\n| amplitude (deg) | first turn | yaw at +1.00 s | yaw at +1.75 s | lateral displacement |\n|---|---|---|---|---|\n";
  const int n = static_cast<int>(amplitudes.size());
  std::vector<scenario::SineWithDwellMetrics> left(n), right(n);
  progress("FMVSS 126: the sine-with-dwell series");
  ProgressBar bar(static_cast<std::size_t>(2 * n), "runs");
  scenario::runInParallel(2 * n, s.jobs, [&](int k) {
    const int i = k / 2;
    const double sign = k % 2 == 0 ? 1.0 : -1.0;
    scenario::ScenarioSpec t = base;
    t.steering.level = sign * std::min(1.0, amplitudes[i] / full);
    // The largest amplitude's runs kept (the series' hardest).
    const std::string keep = i + 1 == n ? telemetryFile(s, sign > 0 ? "fmvss126_largest_left" : "fmvss126_largest_right") : "";
    (sign > 0 ? left : right)[i] = scenario::fmvss126SineWithDwell(run(t, keep).history);
    bar.step();
  });
  if (!s.outDir.empty()) {
    plot(md, {telemetryFile(s, "fmvss126_sis"), png(s, "fmvss126_sis"),
                 "FMVSS 126 slowly increasing steer: lateral acceleration (m/s^2) over the steering input", "steer_in",
                 {"ay_mps2"}});
    plot(md, {telemetryFile(s, "fmvss126_largest_left"), png(s, "fmvss126_largest"),
                 "FMVSS 126 sine with dwell, the largest amplitude: steering input and yaw rate (rad/s)", "time_s",
                 {"steer_in", "yawrate_radps"}});
  }
  for (int i = 0; i < n; ++i)
    for (int side = 0; side < 2; ++side) {
      const scenario::SineWithDwellMetrics& m = side == 0 ? left[i] : right[i];
      char row[200];
      std::snprintf(row, sizeof row, "| %.1f | %s | %.1f %% | %.1f %% | %.2f m |\n", amplitudes[i], side == 0 ? "left" : "right",
                    m.yawRatio1000, m.yawRatio1750, m.lateralDisplacement);
      md << row;
    }
  const scenario::SeriesVerdict a = scenario::fmvss126Verdict(amplitudes, left, A);
  const scenario::SeriesVerdict b = scenario::fmvss126Verdict(amplitudes, right, A);
  md << "\nVerdict: " << (a.pass && b.pass ? "passes" : "fails: " + (a.pass ? b.why : a.why)) << ".\n\n";
}

// ISO 4138: the steering for a 40 m circle at 20 km/h, then the slow speed ramp.
void iso4138(std::ostream& md, const Setup& s) {
  progress("ISO 4138 constant steering-wheel angle: steering for a 40 m circle at 20 km/h");
  scenario::ScenarioSpec spec = shipped("iso4138_constant_steer.toml", s);
  // The path's curvature (yaw rate over speed) before the speed ramp begins.
  auto curvature = [&](double level) {
    scenario::ScenarioSpec t = spec;
    t.steering.level = level;
    t.duration = spec.speedControl.profile.rampStart;
    const Ran r = run(t);
    double sum = 0;
    int k = 0;
    for (size_t i = 0; i < r.history.t.size(); ++i)
      if (r.history.t[i] > t.duration - 0.5 && r.history.speed[i] > 1) sum += r.history.yawRate[i] / r.history.speed[i], ++k;
    return k ? sum / k : 0.0;
  };
  const scenario::Calibration c = scenario::calibrate(curvature, 1.0 / 40.0, spec.steering.level, 0.01);
  spec.steering.level = c.input;
  const Ran r = run(spec, telemetryFile(s, "iso4138_constant_steer"));
  const scenario::SteadyStateMetrics m = scenario::iso4138ConstantSteer(r.history);
  md << "## ISO 4138 constant steering-wheel angle, 20-60 km/h\n\nCalibrated: " << m.steer
     << " deg of steering wheel for a " << (c.response > 0 ? 1 / c.response : 0.0) << " m circle at 20 km/h ("
     << c.tries.size() << " runs).\n\n```\n" << scenario::describe(m) << "```\n\n";
  if (!s.outDir.empty())
    plot(md, {telemetryFile(s, "iso4138_constant_steer"), png(s, "iso4138_constant_steer"),
                 "ISO 4138 constant steering-wheel angle: lateral acceleration (m/s^2) and yaw rate (rad/s) over time",
                 "time_s", {"ay_mps2", "yawrate_radps"}});
  if (m.valid && m.understeerGradient != 0) {
    const double K = m.understeerGradient * M_PI / 180 / kG;  // rad per m/s^2
    const double v = std::sqrt(r.history.wheelbase / std::abs(K));
    md << (K > 0 ? "Characteristic speed" : "Critical speed") << " sqrt(L / |U|): " << v * 3.6 << " km/h.\n\n";
  }
}

// ISO 3888-2: the highest passing speed with the preview driver.
void iso3888(std::ostream& md, const Setup& s) {
  progress("ISO 3888-2: the highest passing speed (preview driver)");
  scenario::ScenarioSpec spec = shipped("iso3888_2_obstacle_avoidance_60.toml", s);
  spec.pathFollower.law = scenario::PathFollowerSpec::Law::Preview;
  scenario::LimitSearchSpec ls;
  ls.jobs = s.jobs;
  const scenario::LimitResult r = scenario::searchLimit(ls, [&](double v) { return scenario::courseTrial(spec, v); });
  md << "## ISO 3888-2 obstacle avoidance\n\nThe preview driver (docs/STANDARD_TESTS.md), throttle released at "
        "the entry gate, entry speed searched from 30 to 100 km/h to 0.5 km/h (" << r.trials.size() << " runs): "
     << r.describe() << ".\n\n";
  if (!s.outDir.empty() && r.anyPass) {
    const std::string csv = telemetryFile(s, "iso3888_2_highest_pass");
    scenario::courseTrial(spec, r.highestPass, csv);
    const scenario::ScenarioSpec at = scenario::courseScenarioAt(spec, r.highestPass);
    const std::string dir = (std::filesystem::path(s.outDir) / "iso3888_2_highest_pass").string();
    std::filesystem::create_directories(dir);
    const std::string why = plotDrive(csv, dir, scenario::Simulation(at).course(), "ISO 3888-2 at the highest passing speed");
    md << (why.empty() ? "Plots: iso3888_2_highest_pass/path.png (the path with the lanes and cones), "
                         "iso3888_2_highest_pass/lateral_acceleration.png.\n\n"
                       : "(no plots: " + why + ")\n\n");
  }
}

int runStandard(const std::string& vehicleFile, const std::string& out, int jobs) {
  Setup s;
  s.vehicleFile = std::filesystem::absolute(vehicleFile).lexically_normal().string();
  s.outDir = out;
  s.jobs = jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (!out.empty()) std::filesystem::create_directories(out);
  std::ostringstream md;
  md << "# Standard tests: " << vehicleFile << "\n\n`bdfcar standard " << vehicleFile
     << "`: each test's amplitude calibrated for this car as its standard prescribes (docs/STANDARD_TESTS.md).\n\n";
  iso7401(md, s);
  fmvss126(md, s);
  iso4138(md, s);
  iso3888(md, s);
  std::fputs(md.str().c_str(), stdout);
  if (!out.empty()) {
    const std::string sheet = (std::filesystem::path(out) / "standard.md").string();
    std::ofstream f(sheet);
    f << md.str();
    f.close();
    if (!f) throw scenario::OutputError("cannot write " + sheet);
    std::fprintf(stderr, "standard: the sheet and the runs' telemetry are in %s\n", out.c_str());
  }
  return kExitOk;
}

}  // namespace

void addStandardCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "standard", "Run every standard test on a vehicle, amplitudes calibrated for it as the standards prescribe");
  auto vehicle = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto jobs = std::make_shared<int>(0);
  cmd->add_option("vehicle", *vehicle, "Vehicle file (assets/vehicles/*.toml)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", *out, "Folder for the sheet (standard.md) and the runs' telemetry");
  cmd->add_option("--jobs,-j", *jobs, "Runs at once (default: the machine's cores)")->check(CLI::Range(0, 256));
  commands.push_back({cmd, [=] { return reportErrors([&] { return runStandard(*vehicle, *out, *jobs); }); }});
}

}  // namespace bdfcar::app
