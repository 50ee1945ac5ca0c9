#include "report/studies.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace bdfcar::app {

std::vector<double> column(const std::vector<vehicle::VehicleSample>& s, const std::string& name) {
  std::vector<double> out;
  for (const auto& x : s) {
    if (name == "t") out.push_back(x.t);
    else if (name == "yawrate") out.push_back(x.yawRate);
    else if (name == "ay") out.push_back(x.ay);
    else if (name == "roll") out.push_back(x.roll);
    else if (name == "z") out.push_back(x.com.z());
    else if (name == "y") out.push_back(x.com.y());
    else if (name == "height") out.push_back(x.chassisOrigin.z());  // the chassis frame, absolute
    else if (name == "FzFL") out.push_back(x.Fz[0]);
    else if (name == "FzFR") out.push_back(x.Fz[1]);
    else if (name == "FzRL") out.push_back(x.Fz[2]);
    else if (name == "FzRR") out.push_back(x.Fz[3]);
    else throw std::logic_error("unknown column " + name);
  }
  if (name == "z" && !out.empty()) {
    const double z0 = out.front();
    for (double& v : out) v -= z0;  // dz_com
  }
  return out;
}

Difference compareAt(const std::vector<double>& refT, const std::vector<double>& ref, const std::vector<double>& runT,
                     const std::vector<double>& run) {
  Difference d;
  double peak = 0, sum = 0;
  for (double v : ref) peak = std::max(peak, std::abs(v));
  size_t n = 0, j = 0;
  for (size_t i = 0; i < run.size() && i < runT.size(); ++i) {
    const double t = runT[i];
    if (refT.empty() || t < refT.front() - 1e-9 || t > refT.back() + 1e-9) continue;
    while (j + 1 < refT.size() && refT[j + 1] <= t) ++j;
    double r = ref[j];
    if (j + 1 < refT.size() && refT[j + 1] > refT[j])
      r += (ref[j + 1] - ref[j]) * std::clamp((t - refT[j]) / (refT[j + 1] - refT[j]), 0.0, 1.0);
    const double e = run[i] - r;
    sum += e * e;
    d.maxAbs = std::max(d.maxAbs, std::abs(e));
    ++n;
  }
  d.rms = n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
  d.rmsPercent = peak > 0 ? 100.0 * d.rms / peak : 0.0;
  return d;
}

std::vector<std::string> hardCaseFiles() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(asset("scenarios/hard")))
    if (e.path().extension() == ".toml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

namespace {

// One timed run: no samples (a telemetry row costs about a residual
// evaluation, sampleVehicle, which would hide what the model costs).
struct TimedRun {
  bool ok = false;
  double perStepUs = 0;
  scenario::StepCost cost;
};
TimedRun timedRun(const scenario::ScenarioSpec& spec) {
  scenario::Simulation sim(spec);
  scenario::RunOptions o;
  o.sample = false;
  o.keepSamples = false;
  const scenario::RunResult timed = scenario::runScenario(sim, o);
  return {timed.ok, 1e6 * timed.wallSeconds / std::max(1L, timed.steps), scenario::stepCost(timed.stepSeconds)};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The medians of timed runs into a summary, and its sampled run.
struct Timings {
  std::vector<double> perStep, p50, p99, max;
  void add(const TimedRun& t) {
    perStep.push_back(t.perStepUs);
    p50.push_back(t.cost.p50);
    p99.push_back(t.cost.p99);
    max.push_back(t.cost.max);
  }
  RunSummary summary(const scenario::ScenarioSpec& spec) const {
    RunSummary s;
    {
      scenario::Simulation sim(spec);
      s.result = scenario::runScenario(sim, scenario::RunOptions{});
    }
    if (!perStep.empty()) {
      s.wallPerStepUs = median(perStep);
      s.stepCost = {median(p50), median(p99), median(max)};
    }
    return s;
  }
};

}  // namespace

RunSummary runRepeated(const scenario::ScenarioSpec& spec, int repeats) {
  Timings t;
  for (int i = 0; i < repeats; ++i) {
    const TimedRun r = timedRun(spec);
    if (!r.ok) break;
    t.add(r);
  }
  return t.summary(spec);
}

PairedSummary runPaired(const scenario::ScenarioSpec& a, const scenario::ScenarioSpec& b, int repeats) {
  Timings ta, tb;
  std::vector<double> ratios;
  for (int i = 0; i < repeats; ++i) {
    const TimedRun ra = timedRun(a), rb = timedRun(b);
    if (!ra.ok || !rb.ok) break;
    ta.add(ra);
    tb.add(rb);
    ratios.push_back(ra.perStepUs / rb.perStepUs);
  }
  PairedSummary p{ta.summary(a), tb.summary(b), 0.0};
  if (!ratios.empty()) p.ratio = median(ratios);
  return p;
}

scenario::ScenarioSpec withIntegrator(scenario::ScenarioSpec s, scenario::IntegratorMethod m, double step, int order,
                                      int newton, int jacobianEvery, bool refresh) {
  s.integrator.method = m;
  s.integrator.step = step;
  if (scenario::stepsPerTick(s.tick, step) == 0) s.tick = step;  // steps longer than the driver's tick
  s.integrator.bdf.order = order;
  s.integrator.bdf.newtonIterations = newton;
  s.integrator.bdf.jacobianEvery = jacobianEvery;
  s.integrator.bdf.refreshWhenNotContracting = refresh;
  // The method as published (no refresh) takes its count in full; bdfcar's
  // policy ends a step's count at the first iteration within tolerance.
  s.fidelity.stopWithinTolerance = refresh;
  return s;
}

// One column of a CSV with a header line; a cell that is not a finite number
// is an error naming the file, the line and the column (never "stod").
std::vector<double> csvColumn(const std::string& path, const std::string& name) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot open the reference CSV");
  std::string line;
  std::getline(f, line);
  std::stringstream h(line);
  int index = -1, i = 0;
  for (std::string c; std::getline(h, c, ','); ++i)
    if (c == name) index = i;
  if (index < 0) throw std::runtime_error(path + ":1: no column '" + name + "' in the header line");
  std::vector<double> out;
  for (int lineNumber = 2; std::getline(f, line); ++lineNumber) {
    std::stringstream r(line);
    std::string cell;
    for (int k = 0; k <= index; ++k) std::getline(r, cell, ',');
    double x = 0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
    if (ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(x))
      throw std::runtime_error(path + ":" + std::to_string(lineNumber) + ": column '" + name +
                               "': expected a finite number, got '" + cell + "'");
    out.push_back(x);
  }
  if (out.empty()) throw std::runtime_error(path + ": no data lines below the header");
  return out;
}

std::string asset(const std::string& rel) { return std::string(BDFCAR_ASSET_DIR) + "/" + rel; }

scenario::ScenarioSpec scenarioWith(const std::string& scenarioFile, const std::string& vehicleFile) {
  scenario::ScenarioSpec s = scenario::loadScenarioFile(asset("scenarios/" + scenarioFile));
  s.vehicleFile = asset("vehicles/" + vehicleFile);
  return s;
}

std::string fmt(const char* format, double value) {
  char b[64];
  std::snprintf(b, sizeof b, format, value);
  return b;
}

scenario::RunResult converged(const scenario::ScenarioSpec& s) {
  scenario::Simulation sim(withIntegrator(s, scenario::IntegratorMethod::Bdf, 0.001, 2, 0, 1));
  return scenario::runScenario(sim, {});
}

std::string divergedCell(const scenario::RunResult& r) {
  return r.failureTime < 0 ? "diverged while settling (t = " + fmt("%.2f s", r.failureTime) + ")"
                           : "diverged at t = " + fmt("%.2f s", r.failureTime);
}

void command(std::ostream& md, const std::string& args) {
  md << "Command (one run): `bdfcar run " << args << " --out run.csv`\n\n";
}

void writePlot(const std::string& dataPath, const std::string& png, const std::string& script) {
  std::ofstream g(png + ".gp");
  g << "set datafile separator ','\nset terminal pngcairo size 1200,800 font ',11'\nset output '" << png << "'\n"
    << "set grid\nset key outside below\n" << script;
  g.close();
  if (std::system(("gnuplot '" + png + ".gp' > /dev/null 2>&1").c_str()) != 0)
    std::fprintf(stderr, "note: gnuplot could not draw %s\n", png.c_str());
  std::filesystem::remove(png + ".gp");
  (void)dataPath;
}

}  // namespace bdfcar::app
