#include "scenario/driver_identification.h"

#include <cmath>
#include <exception>

#include "scenario/simulation.h"

namespace bdfcar::scenario {

Identification identifySingleTrack(const ScenarioSpec& spec, std::shared_ptr<const Scene> scene,
                                   const vehicle::SingleTrack& prior) {
  Identification out{prior, false, ""};
  const double u = spec.initialSpeed;
  if (!(u > 3.0)) {
    out.why = "the start is too slow for a steady turn";
    return out;
  }
  ScenarioSpec probe = spec;
  probe.name = spec.name + " (the preview driver's identification run)";
  probe.pathFollower = {};
  probe.course = {};
  probe.standardTest = StandardTest::None;
  probe.check = {};
  probe.throttle = probe.brake = {};
  probe.steering = {};
  probe.steering.kind = SignalSpec::Kind::Ramp;
  probe.steering.start = 0.5;
  probe.steering.duration = 0.2;
  probe.steering.level = 2.0 / (prior.steadyLateralGain(u) * prior.roadWheelPerSteer);
  probe.steering.asDriverCommand = true;
  probe.speedControl.enabled = true;
  probe.speedControl.profile = {};
  probe.speedControl.profile.target = u;
  probe.duration = 4.0;
  try {
    Simulation sim(buildWorld(probe, std::move(scene)));
    sim.prepare();
    const long ticks = std::lround(probe.duration / probe.tick);
    double vy = 0, r = 0, steer = 0;
    int n = 0;
    for (long k = 0; k < ticks; ++k) {
      sim.beginTick(std::nullopt);
      for (int i = 0; i < sim.stepsPerTick(); ++i)
        if (!sim.step().ok()) {
          out.why = "the identification run failed";
          return out;
        }
      if (sim.time() >= probe.duration - 1.0) {  // the last second: steady
        const vehicle::VehicleSample s = sim.sample();
        vy += s.vy;
        r += s.yawRate;
        steer += sim.steerAt(sim.time());
        ++n;
      }
    }
    vy /= n;
    r /= n;
    const double delta = prior.roadWheelPerSteer * steer / n, m = prior.mass, a = prior.a, b = prior.b, L = a + b;
    const double front = m * u * r * b / L, rear = m * u * r * a / L;
    const double Cf = front / (delta - (vy + a * r) / u), Cr = -rear * u / (vy - b * r);
    if (!(Cf > 0.1 * prior.frontStiffness && Cf < 10 * prior.frontStiffness && Cr > 0.1 * prior.rearStiffness &&
          Cr < 10 * prior.rearStiffness)) {
      out.why = "the identified stiffnesses are not physical";
      return out;
    }
    out.car.frontStiffness = Cf;
    out.car.rearStiffness = Cr;
    out.fitted = true;
  } catch (const std::exception& e) {
    out.why = std::string("the identification run failed: ") + e.what();
  }
  return out;
}

}  // namespace bdfcar::scenario
