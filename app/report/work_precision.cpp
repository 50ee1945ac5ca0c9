// RESULTS.md sections: work-precision diagrams (cost per simulated second
// against error, for integrator settings on smooth and hard manoeuvres) and
// the survival of the hard cases at long steps and with explicit methods.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <vector>

#include "report/studies.h"
#include "scenario/check.h"

namespace bdfcar::app {

namespace {

using scenario::IntegratorMethod;

// A case turns (its errors also as % of a peak) where its converged yaw rate
// reaches this: a lane change at walking pace does, a straight run's drift
// (micro-radians a second) does not.
constexpr double kTurnYawRate = 0.05;  // rad/s

// A case loads its wheels (their loads' errors also as % of the swing) where
// a wheel's converged load swings by this much (max - min) over the
// manoeuvre: relief, braking, a turn do; a steady straight run does not.
constexpr double kLoadSwing = 1000.0;  // N

// The wheel loads' RMS difference to the converged run, as % of each
// wheel's swing there, the largest of the four (negative where no wheel's
// load swings by kLoadSwing): what relief and a straight run's vertical
// dynamics are judged on, where yaw rate and lateral acceleration have no
// peak to divide by.
double wheelLoadError(const std::vector<vehicle::VehicleSample>& fine, const std::vector<vehicle::VehicleSample>& run) {
  double worst = -1;
  for (const char* c : {"FzFL", "FzFR", "FzRL", "FzRR"}) {
    const std::vector<double> ref = column(fine, c);
    if (ref.empty()) continue;
    const auto [lo, hi] = std::minmax_element(ref.begin(), ref.end());
    const double swing = *hi - *lo;
    if (!(swing >= kLoadSwing)) continue;
    const Difference d = compareAt(column(fine, "t"), ref, column(run, "t"), column(run, c));
    worst = std::max(worst, 100.0 * d.rms / swing);
  }
  return worst;
}

// The shortest period of the scripted inputs (a square wave's, a sine's, a
// chirp's at its fastest; infinity for none): a tick longer than half of it
// samples the input below its Nyquist rate, so the run at that tick and the
// converged one see different commands (a square wave sampled on its edges
// takes either level by rounding), and their difference is not the
// integrator's.
double shortestInputPeriod(const scenario::ScenarioSpec& s) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const scenario::SignalSpec* g : {&s.steering, &s.throttle, &s.brake}) {
    using Kind = scenario::SignalSpec::Kind;
    if (g->kind == Kind::Square || g->kind == Kind::Sine || g->kind == Kind::SineWithDwell)
      shortest = std::min(shortest, g->duration);
    if (g->kind == Kind::Chirp && std::max(g->f0, g->f1) > 0) shortest = std::min(shortest, 1.0 / std::max(g->f0, g->f1));
  }
  return shortest;
}

struct Setting {
  std::string label;  // as in the legend and the tables
  int family;         // plot series: 0-2 BDF1-3, 3 Newton / Jacobian variants of BDF2, 4 RK4, 5 Euler
  IntegratorMethod method;
  double step;
  int order, newton, jacobianEvery;
};

std::vector<Setting> settings() {
  std::vector<Setting> s;
  for (int k = 1; k <= 3; ++k)
    for (double h : {0.005, 0.01, 0.02, 0.04})
      s.push_back({"BDF" + std::to_string(k) + " " + fmt("%g ms", 1e3 * h), k - 1, IntegratorMethod::Bdf, h, k, 2, 200});
  s.push_back({"BDF2 10 ms, Newton 1", 3, IntegratorMethod::Bdf, 0.01, 2, 1, 200});
  s.push_back({"BDF2 10 ms, Newton 3", 3, IntegratorMethod::Bdf, 0.01, 2, 3, 200});
  s.push_back({"BDF2 10 ms, Newton to tolerance", 3, IntegratorMethod::Bdf, 0.01, 2, 0, 200});
  s.push_back({"BDF2 10 ms, Jacobian every step", 3, IntegratorMethod::Bdf, 0.01, 2, 2, 1});
  s.push_back({"BDF2 10 ms, Jacobian every 20", 3, IntegratorMethod::Bdf, 0.01, 2, 2, 20});
  for (double h : {0.001, 0.002, 0.005, 0.01}) {
    s.push_back({"RK4 " + fmt("%g ms", 1e3 * h), 4, IntegratorMethod::Rk4, h, 2, 2, 200});
    s.push_back({"Euler " + fmt("%g ms", 1e3 * h), 5, IntegratorMethod::SemiImplicitEuler, h, 2, 2, 200});
  }
  return s;
}

const char* kFamily[] = {"BDF1 (2 Newton, J/200)", "BDF2 (2 Newton, J/200)", "BDF3 (2 Newton, J/200)",
                         "BDF2 10 ms: Newton 1 / 3 / to tolerance, Jacobian every 1 / 20", "RK4",
                         "semi-implicit Euler"};

struct Point {
  std::string label;
  int family = 0;
  bool diverged = false;
  double cost = 0;   // ms of wall time per simulated second
  double error = 0;  // % of the converged run's peak, the larger of yaw rate and lateral acceleration
};

// RMS differences of yaw rate and lateral acceleration to a converged run, as
// % of its peaks; the larger of the two.
double relativeError(const std::vector<vehicle::VehicleSample>& fine, const std::vector<vehicle::VehicleSample>& run) {
  const auto diff = [&](const char* c) {
    return compareAt(column(fine, "t"), column(fine, c), column(run, "t"), column(run, c)).rmsPercent;
  };
  return std::max(diff("yawrate"), diff("ay"));
}

// The settings no other setting beats on both cost and error, cheapest first.
std::vector<const Point*> paretoFront(const std::vector<Point>& pts) {
  std::vector<const Point*> ok;
  for (const Point& p : pts)
    if (!p.diverged) ok.push_back(&p);
  std::sort(ok.begin(), ok.end(), [](const Point* a, const Point* b) { return a->cost < b->cost; });
  std::vector<const Point*> front;
  double best = INFINITY;
  for (const Point* p : ok)
    if (p->error < best) {
      front.push_back(p);
      best = p->error;
    }
  return front;
}

struct WpCase {
  std::string name, file;
  std::string vehicle = "sedan.toml";
  bool pointOnRelief = false;  // relief felt by the point contact (a case the enveloping tyre also runs)
};

// What decides a recommendation: per setting, the worst error over the
// cases, the total cost and whether any run diverged.
struct Tally {
  std::map<std::string, double> worstError, totalCost;
  std::map<std::string, bool> everDiverged;
  void add(const Point& p) {
    worstError[p.label] = std::max(worstError[p.label], p.diverged ? INFINITY : p.error);
    totalCost[p.label] += p.cost;
    everDiverged[p.label] = everDiverged[p.label] || p.diverged;
  }
  // Among settings whose step is the driver's tick or longer (one step per
  // 10 ms tick: the cheapest interactive loop), the cheapest in total that
  // is within 1 % on every case and never diverges; empty if none.
  std::string pick(const std::vector<Setting>& all) const {
    std::string best;
    double bestCost = INFINITY;
    for (const Setting& s : all) {
      if (s.step < 0.01 - 1e-12 || !worstError.count(s.label)) continue;
      if (!everDiverged.at(s.label) && worstError.at(s.label) <= 1.0 && totalCost.at(s.label) < bestCost) {
        best = s.label;
        bestCost = totalCost.at(s.label);
      }
    }
    return best;
  }
};

}  // namespace

void workPrecisionSection(std::ostream& md, const std::string& imageDir) {
  const std::vector<WpCase> cases = {{"J-turn", "jturn.toml"},
                                     {"lane change", "lane_change.toml"},
                                     {"curb strike", "hard/curb_strike.toml", "sedan.toml", true},
                                     {"curb strike, enveloping tyres", "hard/curb_strike.toml", "sedan_envelope.toml"},
                                     {"sine with dwell", "hard/sine_with_dwell_80.toml"},
                                     {"rough road", "hard/rough_lane_change.toml", "sedan.toml", true},
                                     {"rough road, enveloping tyres", "hard/rough_lane_change.toml", "sedan_envelope.toml"}};
  const std::vector<Setting> all = settings();
  md << "## 5c. Work-precision diagrams\n\n"
     << "Cost (wall time per simulated second, one run each, manoeuvre only) against error (RMS of yaw rate and "
     << "lateral acceleration against the same case converged at 0.5 ms, BDF2 with Newton to tolerance and "
     << "the Jacobian at every step; the larger of the two, as % of the converged run's peak), sedan.toml; "
     << "the curb and the rough road also on enveloping tyres (sedan_envelope.toml: physics/tyre/envelope.h, the "
     << "converged run on them too). "
     << "BDF orders 1-3 at 5, 10, 20 and 40 ms with the default policy (at most 2 Newton iterations, Jacobian every "
     << "200 steps); at 10 ms BDF2 with Newton 1, 3 and to tolerance and the Jacobian every step or every 20; RK4 "
     << "and semi-implicit Euler at 1, 2, 5 and 10 ms. A diverged run is drawn at the top of its panel "
     << "(crosses) and listed below, not dropped.\n\n";
  Tally everyCase, enveloping;  // enveloping: relief on enveloping tyres only
  std::vector<std::string> dataFiles;
  md << "| case | Pareto front, cheapest first (cost ms/s, error %) | diverged |\n|---|---|---|\n";
  for (const WpCase& c : cases) {
    const scenario::ScenarioSpec base = scenarioWith(c.file, c.vehicle);
    scenario::Simulation fineSim(withIntegrator(base, IntegratorMethod::Bdf, 0.0005, 2, 0, 1));
    const scenario::RunResult fine = scenario::runScenario(fineSim, {});
    if (!fine.ok) {
      md << "| " << c.name << " | the 0.5 ms run failed: " << fine.failure << " | |\n";
      continue;
    }
    std::vector<Point> pts;
    for (const Setting& s : all) {
      scenario::Simulation sim(withIntegrator(base, s.method, s.step, s.order, s.newton, s.jacobianEvery));
      scenario::RunOptions o;
      o.keepStepCost = false;
      const scenario::RunResult r = scenario::runScenario(sim, o);
      Point p;
      p.label = s.label;
      p.family = s.family;
      p.diverged = !r.ok;
      p.cost = 1e3 * r.wallSeconds / std::max(1e-9, r.simulatedSeconds);
      p.error = r.ok ? relativeError(fine.samples, r.samples) : 0;
      pts.push_back(p);
      everyCase.add(p);
      if (!c.pointOnRelief) enveloping.add(p);
    }
    // Data for the plot: one block per family, then the diverged points.
    const std::string data = imageDir + "/wp_" + std::to_string(dataFiles.size()) + ".dat";
    double top = 1e-6, right = 1e-3;
    for (const Point& p : pts)
      if (!p.diverged) top = std::max(top, p.error), right = std::max(right, p.cost);
    {
      std::ofstream d(data);
      for (int f = 0; f < 6; ++f) {
        for (const Point& p : pts)
          if (p.family == f && !p.diverged) d << p.cost << " " << std::max(p.error, 1e-6) << "\n";
        d << "\n\n";
      }
      bool any = false;
      for (const Point& p : pts)
        if (p.diverged) {
          // A run that diverged early has a tiny simulated time: its cost is
          // drawn at most at twice the costliest run that did not.
          d << std::clamp(p.cost, 1e-3, 2 * right) << " " << 3 * top << "\n";
          any = true;
        }
      if (!any) d << "NaN NaN\n";
    }
    dataFiles.push_back(data);
    md << "| " << c.name << " | ";
    bool first = true;
    for (const Point* p : paretoFront(pts)) {
      md << (first ? "" : "; ") << p->label << " (" << fmt("%.3g", p->cost) << ", " << fmt("%.2g", p->error) << ")";
      first = false;
    }
    md << " | ";
    first = true;
    for (const Point& p : pts)
      if (p.diverged) {
        md << (first ? "" : ", ") << p.label;
        first = false;
      }
    md << (first ? "none" : "") << " |\n";
  }
  // The recommendations: the worst case decides, not the mean (a driving
  // simulator needs the tick held on every road).
  const std::string pick = everyCase.pick(all), pickEnvelope = enveloping.pick(all);
  md << "\nRecommended interactive setting: **" << (pick.empty() ? std::string("none within 1 %") : pick) << "**";
  if (!pick.empty())
    md << ": of the settings with one step per 10 ms tick or fewer, the cheapest over these cases that never "
       << "diverges and stays within 1 % of peak on every one (worst " << fmt("%.2g %%", everyCase.worstError.at(pick))
       << "); a driving simulator needs the tick held on every road, so the worst case decides, not the mean";
  md << ". With enveloping tyres on relief (the curb and the rough road on sedan_envelope.toml in place of the "
     << "point contact): **" << (pickEnvelope.empty() ? std::string("none within 1 %") : pickEnvelope) << "**";
  if (!pickEnvelope.empty())
    md << " (worst " << fmt("%.2g %%", enveloping.worstError.at(pickEnvelope)) << ")";
  md << ".\n\n";
  // The figure: one log-log panel per case.
  const std::string png = imageDir + "/work_precision.png";
  std::string script = "set terminal pngcairo size 1500,1400 font ',10'\nset output '" + png +
                       "'\nset multiplot layout 3,3\nset logscale xy\nset format y '%g'\nset xlabel 'ms of wall time per "
                       "simulated second'\nset ylabel 'RMS error, % of peak'\nset key off\n";
  const char* style[] = {"lp pt 7 lc rgb '#1f77b4'", "lp pt 7 lc rgb '#2ca02c'", "lp pt 7 lc rgb '#9467bd'",
                         "p pt 5 ps 1.3 lc rgb '#ff7f0e'", "lp pt 9 lc rgb '#d62728'", "lp pt 11 lc rgb '#8c564b'"};
  for (size_t i = 0; i < dataFiles.size(); ++i) {
    script += "set title '" + cases[i].name + "'\nplot ";
    for (int f = 0; f < 6; ++f) script += "'" + dataFiles[i] + "' index " + std::to_string(f) + " w " + style[f] + ", ";
    script += "'" + dataFiles[i] + "' index 6 w p pt 2 ps 2 lc rgb 'black'\n";
  }
  // The legend in the panel after the last case.
  script += "unset logscale\nunset title\nunset xlabel\nunset ylabel\nunset border\nunset tics\nset key left center "
            "Left reverse box\nset xrange [0:1]\nset yrange [0:1]\nplot ";
  for (int f = 0; f < 6; ++f) script += std::string("NaN w ") + style[f] + " t '" + kFamily[f] + "', ";
  script += "NaN w p pt 2 ps 2 lc rgb 'black' t 'diverged (drawn at the top)'\nunset multiplot\n";
  {
    std::ofstream g(png + ".gp");
    g << script;
  }
  if (std::system(("gnuplot '" + png + ".gp' > /dev/null 2>&1").c_str()) != 0)
    std::fprintf(stderr, "note: gnuplot could not draw %s\n", png.c_str());
  std::filesystem::remove(png + ".gp");
  for (const std::string& f : dataFiles) std::filesystem::remove(f);
  md << "![Work-precision diagrams](images/work_precision.png)\n\n";
}

void survivalSection(std::ostream& md) {
  md << "## 5d. The hard cases at long steps and with explicit methods\n\n"
     << "Each file of assets/scenarios/hard/ with its [check] (as `bdfcar check`): BDF2 with the default policy "
     << "at 10, 20 and 40 ms (the driver's tick set to the step where it is longer), RK4 and semi-implicit "
     << "Euler at 10 ms. A cell says whether the check holds and how far the run is from the same case "
     << "converged at 1 ms (Newton to tolerance, Jacobian every step) with the same driver's tick (a longer "
     << "tick samples the driver's commands at other times: that changes the scenario's input, not the "
     << "integrator's error): RMS of yaw rate "
     << "(rad/s) / lateral acceleration (m/s^2), absolute, and in brackets the larger of the two as % of the "
     << "converged run's peak where the case turns (a peak yaw rate of " << fmt("%.2g", kTurnYawRate)
     << " rad/s or more; a straight run has no peak to divide by). Where the tick is longer than half the "
     << "shortest period of a scripted input, the input itself is aliased (the run and its converged twin "
     << "see different commands): the cell says so and gives no % (the case is then not one the step "
     << "length can be judged on). Then, where a wheel's converged load swings by "
     << fmt("%g kN", kLoadSwing / 1e3) << " or more, *load*: the RMS difference of the wheel loads as % of "
     << "each one's swing (max - min) in the converged run, the largest of the four (the vertical dynamics, "
     << "which a straight run over relief is judged on).\n\n"
     << "| case | BDF2 10 ms | BDF2 20 ms | BDF2 40 ms | RK4 10 ms | Euler 10 ms |\n|---|---|---|---|---|---|\n";
  const std::vector<std::string> files = hardCaseFiles();
  struct Column {
    IntegratorMethod method;
    double step;
  };
  const std::vector<Column> cols = {{IntegratorMethod::Bdf, 0.01},
                                    {IntegratorMethod::Bdf, 0.02},
                                    {IntegratorMethod::Bdf, 0.04},
                                    {IntegratorMethod::Rk4, 0.01},
                                    {IntegratorMethod::SemiImplicitEuler, 0.01}};
  std::vector<int> survived(cols.size(), 0);
  std::vector<std::pair<double, std::string>> worst(cols.size(), {-1.0, ""});  // % of peak, case
  std::vector<std::pair<double, std::string>> worstLoad(cols.size(), {-1.0, ""});  // % of swing, case
  for (const auto& f : files) {
    const scenario::ScenarioSpec base = scenario::loadScenarioFile(f);
    std::map<double, scenario::RunResult> fineAtTick;  // the converged run for each driver's tick
    md << "| " << base.name;
    for (size_t k = 0; k < cols.size(); ++k) {
      std::vector<vehicle::VehicleSample> samples;
      const scenario::ScenarioSpec spec = withIntegrator(base, cols[k].method, cols[k].step, 2, 2, 200);
      const scenario::CheckResult r = scenario::checkScenario(spec, &samples);
      md << " | ";
      if (!r.passed) {
        // A divergence by its time (the check's text names the constraint or
        // coordinate; `bdfcar check` prints it whole), other failures as worded.
        const std::string why = r.failures.empty() ? std::string("?") : r.failures.front();
        double t = 0;
        if (std::sscanf(why.c_str(), "the run failed at t = %lf", &t) == 1)
          md << (t < 0 ? "diverged while settling" : "diverged at t = " + fmt("%.2f s", t));
        else
          md << "fails: " << why;
        continue;
      }
      ++survived[k];
      md << "ok";
      if (!fineAtTick.count(spec.tick)) {
        scenario::ScenarioSpec atTick = base;
        atTick.tick = spec.tick;
        fineAtTick.emplace(spec.tick, converged(atTick));
      }
      const scenario::RunResult& fine = fineAtTick.at(spec.tick);
      if (fine.ok && !samples.empty()) {
        const auto diff = [&](const char* c) {
          return compareAt(column(fine.samples, "t"), column(fine.samples, c), column(samples, "t"), column(samples, c));
        };
        const Difference yaw = diff("yawrate"), ay = diff("ay");
        md << ", " << fmt("%.2g", yaw.rms) << " / " << fmt("%.2g", ay.rms);
        double peakYaw = 0;
        for (double x : column(fine.samples, "yawrate")) peakYaw = std::max(peakYaw, std::abs(x));
        const bool aliased = 2 * spec.tick > shortestInputPeriod(spec);
        if (aliased) {
          md << " (input aliased: its period " << fmt("%g ms", 1e3 * shortestInputPeriod(spec)) << ", the tick "
             << fmt("%g ms", 1e3 * spec.tick) << ")";
        } else if (peakYaw >= kTurnYawRate) {
          const double percent = std::max(yaw.rmsPercent, ay.rmsPercent);
          md << " (" << fmt("%.2g", percent) << " %)";
          if (percent > worst[k].first) worst[k] = {percent, base.name};
        }
        if (const double load = aliased ? -1.0 : wheelLoadError(fine.samples, samples); load >= 0) {
          md << "; load " << fmt("%.2g", load) << " %";
          if (load > worstLoad[k].first) worstLoad[k] = {load, base.name};
        }
      }
    }
    md << " |\n";
  }
  md << "| **checks held** |";
  for (int n : survived) md << " " << n << " of " << files.size() << " |";
  md << "\n| **largest % of peak of a turning case that held** |";
  for (const auto& [percent, name] : worst) md << " " << (percent < 0 ? std::string("-") : fmt("%.2g %%", percent) + " (" + name + ")") << " |";
  md << "\n| **largest load error of a case that held, % of swing** |";
  for (const auto& [percent, name] : worstLoad) md << " " << (percent < 0 ? std::string("-") : fmt("%.2g %%", percent) + " (" + name + ")") << " |";
  md << "\n\nCommand: `bdfcar check --step 0.02 --tick 0.02` (and `--integrator rk4` / `euler` at 10 ms).\n\n";
}

}  // namespace bdfcar::app
