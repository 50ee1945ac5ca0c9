#include "scenario/batch_run.h"

#include <chrono>
#include <cmath>
#include <memory>

namespace bdfcar::scenario {

RunResult runScenario(Simulation& sim, const RunOptions& options) {
  RunResult r;
  try {
    r.equilibrium = sim.prepare();
  } catch (const std::exception& e) {
    r.ok = false;
    r.failure = e.what();
    r.failureTime = sim.time();
    return r;
  }
  std::unique_ptr<TelemetryWriter> writer;
  if (!options.telemetryPath.empty()) writer = std::make_unique<TelemetryWriter>(options.telemetryPath, sim.vehicle());
  const ScenarioSpec& spec = sim.spec();
  std::optional<CourseJudge> judge;
  if (sim.course()) {
    const auto& g = sim.vehicle().spec.geometry;
    judge.emplace(*sim.course(), g.length, vehicleWidth(sim.vehicle()), g.bodyOffset);
  }
  const double h = spec.integrator.step;
  const long steps = std::lround(spec.duration / h);
  const long every = std::max(1L, std::lround(spec.outputInterval / h));
  int lastIterations = 0;
  double lastCorrection = 0;
  auto record = [&] {
    if (!options.sample) return;
    const vehicle::VehicleSample s = sim.sample();
    const DriverInput in = sim.lastInput();
    TelemetryInputs ti{sim.steerAt(s.t), in.throttle, in.brake, lastIterations, lastCorrection};
    if (writer) writer->write(s, ti);
    if (options.keepSamples) {
      r.samples.push_back(s);
      r.steerInputs.push_back(ti.steer);
    }
    if (judge) judge->update(s);
    if (options.onSample) options.onSample(s);
  };
  record();
  const auto wall0 = std::chrono::steady_clock::now();
  for (long i = 1; i <= steps; ++i) {
    const integ::StepReport rep = sim.step();
    ++r.steps;
    if (!rep.ok()) {
      r.ok = false;
      r.failureTime = sim.time();
      r.failure = std::string(integ::stepStatusName(rep.status)) + ": " + rep.message.c_str();
      break;
    }
    lastIterations = rep.iterations;
    lastCorrection = rep.correction;
    if (i % every == 0) record();
  }
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  r.simulatedSeconds = r.steps * h;
  if (judge) r.course = judge->result();
  r.counters = sim.integrator().counters();
  r.timers = sim.integrator().timers();
  return r;
}

}  // namespace bdfcar::scenario
