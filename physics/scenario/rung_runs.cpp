#include "scenario/rung_runs.h"

#include <sstream>

#include "scenario/simulation.h"

namespace bdfcar::scenario {

ScenarioSpec rungRunBase(const ScenarioSpec& scene) {
  ScenarioSpec s;
  s.sourceFile = scene.sourceFile;
  s.vehicleFile = scene.vehicleFile;
  s.vehicleSettings = scene.vehicleSettings;
  s.integrator = scene.integrator;
  s.tick = scene.tick;
  s.outputInterval = scene.tick;
  s.initialSpeed = kRungRunSpeed;
  s.settleTime = 1.0;
  s.duration = 4.0;
  s.speedControl.enabled = true;
  s.speedControl.profile.target = kRungRunSpeed;
  return s;
}

SignalSpec roadWheelRamp(double angle) {
  SignalSpec s;
  s.kind = SignalSpec::Kind::Ramp;
  s.unit = SignalSpec::Unit::RoadWheelAngle;
  s.start = 0.5;
  s.duration = 0.2;
  s.level = angle;
  return s;
}

SignalSpec signalTable(std::vector<double> times, std::vector<double> values) {
  SignalSpec s;
  s.kind = SignalSpec::Kind::Table;
  s.times = std::move(times);
  s.values = std::move(values);
  return s;
}

std::string rungRunsKey(const ScenarioSpec& scene) {
  std::ostringstream k;
  k.precision(17);
  k << scene.vehicleFile;
  for (const config::Setting& s : scene.vehicleSettings) k << '|' << s.key << '=' << s.value;
  const IntegratorSpec& i = scene.integrator;
  const integ::BdfOptions& b = i.bdf;
  k << '|' << static_cast<int>(i.method) << ' ' << i.step << ' ' << scene.tick << ' ' << b.order << ' '
    << b.newtonIterations << ' ' << b.maxNewtonIterations << ' ' << b.atol << ' ' << b.rtol << ' ' << b.jacobianEvery
    << ' ' << b.refreshWhenNotContracting << ' ' << b.contractionLimit << ' ' << b.largeCorrection << ' ' << b.lowSpeedTolerance << ' '
    << b.chordContinuation << ' ' << b.fastColumnRescue << ' ' << b.fastRowSolve << ' ' << static_cast<int>(b.startUp) << ' ' << b.refineError
    << ' ' << b.refineDepth << ' ' << b.refineFromFirstIterate << ' ' << b.carryRefinedPieces << ' '
    << b.keepFactorizations << ' '
    << scene.fidelity.planarClosedForm << ' ' << scene.fidelity.kinematicClosedForm << ' '
    << scene.fidelity.newtonIterations << ' ' << scene.fidelity.stopWithinTolerance;
  return k.str();
}

RunResult runOnModel(const ScenarioSpec& s, const vehicle::Vehicle& linkage, const vehicle::Vehicle& model) {
  RunResult r;
  try {
    Simulation sim(buildWorld(s, linkage, model));
    RunOptions o;
    o.keepSamples = true;
    r = runScenario(sim, o);
  } catch (const std::exception& e) {
    r.ok = false;
    r.failure = e.what();
  }
  return r;
}

SteadyState steadyState(const RunResult& r) {
  SteadyState s;
  if (!r.ok || r.samples.empty()) return s;
  const double from = r.samples.back().t - 1.0;
  int n = 0;
  for (const vehicle::VehicleSample& x : r.samples) {
    if (x.t < from) continue;
    s.ay += x.ay;
    s.roll += x.roll;
    ++n;
  }
  if (n == 0) return s;
  s.ay /= n;
  s.roll /= n;
  s.ok = true;
  return s;
}

}  // namespace bdfcar::scenario
