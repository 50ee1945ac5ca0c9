#include "scenario/check.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace bdfcar::scenario {

const char* outcomeName(CheckSpec::Outcome o) {
  switch (o) {
    case CheckSpec::Outcome::Survives: return "survives";
    case CheckSpec::Outcome::ComesToRest: return "comes to rest";
    case CheckSpec::Outcome::DrivesOn: return "drives on";
    case CheckSpec::Outcome::StaysOnFourWheels: return "stays on four wheels";
    case CheckSpec::Outcome::LandsAndDrivesOn: return "lands and drives on";
  }
  return "?";
}

namespace {

std::string format(const char* fmt, double a, double b = 0) {
  char text[160];
  std::snprintf(text, sizeof text, fmt, a, b);
  return text;
}

// What the samples of a run show, gathered as it goes.
struct Watch {
  double z0 = NAN, maxSpeed = 0, maxRise = 0, longestLift = 0;
  std::array<double, 4> lift{};   // s each wheel has been off the ground
  bool allAirborne = false, nonFinite = false;
  Simulation::ConstraintViolation worst;
  vehicle::VehicleSample last;
};

}  // namespace

CheckResult checkScenario(const ScenarioSpec& spec, std::vector<vehicle::VehicleSample>* samples) {
  CheckResult r;
  r.name = spec.name;
  r.file = spec.sourceFile;
  const CheckSpec& c = spec.check;
  Simulation sim(spec);
  Watch w;
  RunOptions o;
  o.keepSamples = samples != nullptr;
  o.onSample = [&](const vehicle::VehicleSample& s) {
    if (!s.com.allFinite() || !std::isfinite(s.speed)) w.nonFinite = true;
    if (std::isnan(w.z0)) w.z0 = s.com.z();
    const auto v = sim.constraintViolation();
    w.worst.position = std::max(w.worst.position, v.position);
    w.worst.velocity = std::max(w.worst.velocity, v.velocity);
    w.worst.acceleration = std::max(w.worst.acceleration, v.acceleration);
    w.maxSpeed = std::max(w.maxSpeed, s.speed);
    w.maxRise = std::max(w.maxRise, s.com.z() - w.z0);
    int grounded = 0;
    for (int k = 0; k < 4; ++k) {
      w.lift[k] = s.inContact[k] ? 0.0 : w.lift[k] + spec.outputInterval;
      w.longestLift = std::max(w.longestLift, w.lift[k]);
      grounded += s.inContact[k] ? 1 : 0;
    }
    if (grounded == 0 && s.t > 0) w.allAirborne = true;
    w.last = s;
  };
  RunResult run;
  try {
    run = runScenario(sim, o);
  } catch (const PrepareError& e) {
    // The car cannot start in this scene (a vehicle that does not assemble,
    // the planar rung on a slope): the case fails with the reason, and a
    // batch of cases goes on with the next.
    r.passed = false;
    r.outcome = "could not start";
    r.failures.push_back(e.what());
    return r;
  }
  if (samples) *samples = std::move(run.samples);
  r.cost = stepCost(run.stepSeconds);
  r.counters = run.counters;
  r.simulated = run.simulatedSeconds;
  r.wall = run.wallSeconds;
  r.worst = w.worst;
  r.maxSpeed = w.maxSpeed;
  r.maxRise = w.maxRise;
  auto fail = [&](const std::string& why) {
    r.passed = false;
    r.failures.push_back(why);
  };
  if (!run.ok) fail(format("the run failed at t = %.3f s: ", run.failureTime) + run.failure);
  if (w.nonFinite) fail("a non-finite state");
  if (w.worst.position > c.maxConstraintPosition)
    fail(format("constraint drift %.3g m above %.3g m", w.worst.position, c.maxConstraintPosition));
  if (w.worst.velocity > c.maxConstraintVelocity)
    fail(format("velocity constraint drift %.3g m/s above %.3g m/s", w.worst.velocity, c.maxConstraintVelocity));
  if (w.worst.acceleration > c.maxConstraintAcceleration)
    fail(format("acceleration constraint drift %.3g above %.3g m/s^2", w.worst.acceleration, c.maxConstraintAcceleration));
  if (w.maxSpeed > c.maxSpeed) fail(format("speed %.1f m/s above %.1f m/s", w.maxSpeed, c.maxSpeed));
  if (w.maxRise > c.maxRise) fail(format("the centre of mass rose %.2f m, more than %.2f m", w.maxRise, c.maxRise));
  const vehicle::VehicleSample& e = w.last;
  const int down = e.inContact[0] + e.inContact[1] + e.inContact[2] + e.inContact[3];
  const bool fourDown = down == 4;
  using O = CheckSpec::Outcome;
  switch (c.outcome) {
    case O::Survives: r.outcome = format("survives, %.1f m/s at the end", e.speed); break;
    case O::ComesToRest:
      r.outcome = format("%.3f m/s at t = %.1f s", e.speed, e.t);
      if (e.speed > c.restSpeed) fail(format("not at rest: %.3f m/s at the end (rest: %.3f m/s)", e.speed, c.restSpeed));
      break;
    case O::DrivesOn:
      r.outcome = format("%.1f m/s, %.0f wheels down at the end", e.speed, down);
      if (!fourDown || e.speed < 1.0) fail("does not drive on: not on four wheels and rolling at the end");
      break;
    case O::StaysOnFourWheels:
      r.outcome = format("longest wheel lift %.2f s", w.longestLift);
      if (w.longestLift > c.maxWheelLift)
        fail(format("a wheel was off the ground for %.2f s (at most %.2f s)", w.longestLift, c.maxWheelLift));
      break;
    case O::LandsAndDrivesOn:
      r.outcome = format(w.allAirborne ? "airborne, then %.1f m/s on %.0f wheels" : "never airborne; %.1f m/s on %.0f wheels",
                         e.speed, down);
      if (!w.allAirborne) fail("never had all four wheels off the ground");
      if (!fourDown || e.speed < 1.0) fail("did not land and drive on");
      break;
  }
  return r;
}

}  // namespace bdfcar::scenario
