// RESULTS.md section: the drivable sedan's powertrain (sedan_drive.toml):
// its gears, a full-throttle run from rest (shift points, 0-100 km/h, the
// speed after 60 s), and what the engine as a state costs per step against
// the reference sedan on the same manoeuvre.
#include "report/studies.h"

#include <cmath>

#include "vehicle/powertrain.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar::app {

namespace {

// Full throttle from rest, tick by tick: where each upshift begins and when 100 km/h is passed.
void fullThrottle(std::ostream& md) {
  const std::string file = "scenarios/powertrain/full_throttle_from_rest.toml";
  scenario::Simulation sim(scenario::loadScenarioFile(asset(file)));
  sim.prepare();
  md << "Full throttle from rest (`" << file << "`): each upshift begins where the gear turns the engine at the "
     << "full-throttle upshift speed (the clutch then opens, the gear changes, the clutch closes).\n\n"
     << "| shift | t (s) | speed (km/h) | engine (rpm), one tick into the shift |\n|---|---|---|---|\n";
  bool was = false;
  double t100 = -1;
  const int ticks = static_cast<int>(std::lround(sim.spec().duration / sim.spec().tick));
  for (int i = 0; i < ticks; ++i) {
    sim.beginTick(std::nullopt);
    for (int k = 0; k < sim.stepsPerTick(); ++k)
      if (!sim.step().ok()) {
        md << "\nThe run failed at t = " << sim.time() << " s.\n\n";
        return;
      }
    const vehicle::VehicleSample s = sim.sample();
    if (t100 < 0 && s.vx >= 100 / 3.6) t100 = s.t;
    const bool now = sim.transmission()->shifting();
    if (now && !was)
      md << "| " << sim.transmission()->state().gear << " -> " << sim.transmission()->state().nextGear << " | "
         << fmt("%.2f", s.t) << " | " << fmt("%.1f", s.vx * 3.6) << " | "
         << fmt("%.0f", sim.powertrainChannels().engineRpm) << " |\n";
    was = now;
  }
  const vehicle::VehicleSample end = sim.sample();
  md << "\n0-100 km/h in " << fmt("%.2f", t100) << " s; after " << fmt("%.0f", sim.spec().duration) << " s "
     << fmt("%.1f", end.vx * 3.6) << " km/h in gear " << sim.powertrainChannels().gear << " at "
     << fmt("%.0f", sim.powertrainChannels().engineRpm) << " rpm. The top speed where the engine's power meets "
     << "drag and rolling resistance, the shift points, the idle governor's droop, the rev limiter and the "
     << "handbrake on a 10 % slope are checked against hand calculations in tests/test_powertrain.cpp.\n\n";
  command(md, "assets/" + file);
}

// When the car next crosses the start line (x = 5 m, heading +x, on the
// circuit's main straight) after having left it: its lap time.
double lapTime(const std::vector<vehicle::VehicleSample>& samples) {
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i].t > 60 && samples[i - 1].com.x() < 5 && samples[i].com.x() >= 5 && std::abs(samples[i].com.y()) < 10)
      return samples[i].t;
  return -1;
}

// A lap of the proving ground's circuit from rest: its time, what the model
// chosen by the scene costs and how far it is from the linkage's lap.
void provingGroundLap(std::ostream& md, int repeats) {
  const std::string file = "scenarios/proving_ground/circuit_lap.toml";
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset(file));
  scenario::ScenarioSpec full = spec;
  full.fidelity.automatic = false;
  full.fidelity.suspension = vehicle::Fidelity::Linkage;
  const PairedSummary paired = runPaired(spec, full, repeats);
  const RunSummary &scene = paired.a, &linkage = paired.b;
  if (!scene.result.ok || !linkage.result.ok) {
    md << "The proving-ground lap failed: " << (scene.result.ok ? linkage.result.failure : scene.result.failure)
       << "\n\n";
    return;
  }
  const scenario::RunResult& a = scene.result;
  const scenario::StepCost& ca = scene.stepCost, &cl = linkage.stepCost;
  const std::vector<double> t = column(a.samples, "t"), tl = column(linkage.result.samples, "t");
  const Difference yaw = compareAt(tl, column(linkage.result.samples, "yawrate"), t, column(a.samples, "yawrate"));
  const Difference ay = compareAt(tl, column(linkage.result.samples, "ay"), t, column(a.samples, "ay"));
  md << "A lap of the proving ground (`" << file << "`, assets/terrain/proving_ground.toml): from rest on the "
     << "start line, the path follower on the 2.90 km circuit's centre line, the speed hold at 60 km/h, the "
     << "model chosen by the scene (`auto`). Lap time " << fmt("%.1f", lapTime(a.samples)) << " s. Steps on "
     << "the linkage / kinematic / planar model: " << a.stepsPerModel[0] << " / " << a.stepsPerModel[1] << " / "
     << a.stepsPerModel[2] << " (" << a.fidelitySwitches << " switches: the kinematic model where the road "
     << "ahead has curbs). Median over " << repeats << " runs of the wall time per step (no telemetry): "
     << fmt("%.1f", scene.wallPerStepUs) << " us, against " << fmt("%.1f", linkage.wallPerStepUs)
     << " us for the same lap on the linkage throughout, the two run in turn (ratio, the median of the "
     << repeats << " pairs' own: " << fmt("%.2f", paired.ratio) << "); per step p50 / p99 / max (each the median of the runs' own) "
     << fmt("%.1f", ca.p50) << " / " << fmt("%.1f", ca.p99) << " / " << fmt("%.0f", ca.max) << " us (linkage "
     << fmt("%.1f", cl.p50) << " / " << fmt("%.1f", cl.p99) << " / " << fmt("%.0f", cl.max) << " us). The "
     << "scene's lap against the linkage's: yaw rate " << fmt("%.2f", yaw.rmsPercent) << " %, lateral "
     << "acceleration " << fmt("%.2f", ay.rmsPercent) << " % (RMS as % of peak).\n\n";
  command(md, "assets/" + file);
}

}  // namespace

void powertrainSection(std::ostream& md, int repeats) {
  const vehicle::Vehicle car = vehicle::buildVehicle(vehicle::loadVehicleFile(asset("vehicles/sedan_drive.toml")));
  md << "## 5g. The drivable sedan: powertrain\n\n"
     << "`assets/vehicles/sedan_drive.toml`: the reference sedan's linkage and tyres with an engine, a six-speed "
     << "automated gearbox and an open differential (docs/VEHICLES.md, `powertrain`). The engine is a rotor body "
     << "on a crank joint, its speed a state of the implicit integration; the clutch is a stiff stick-slip law "
     << "inside the residual. `bdfcar info assets/vehicles/sedan_drive.toml`:\n\n```\n"
     << vehicle::describePowertrain(*car.spec.powertrain, car.spec.geometry.wheelRadius) << "```\n\n";
  fullThrottle(md);
  provingGroundLap(md, repeats);
  // The cost of the engine, the clutch and the transmission: the J-turn with each car (the powertrain's
  // speed hold works the throttle), the median wall time per step, measured in one run of the report.
  const RunSummary ref = runRepeated(scenarioWith("jturn.toml", "sedan.toml"), repeats);
  const RunSummary drive = runRepeated(scenarioWith("jturn.toml", "sedan_drive.toml"), repeats);
  md << "What the powertrain costs: the J-turn at the paper's setting with each car (the drivable one's speed "
     << "hold works its throttle), median wall time per step over " << repeats << " runs: reference sedan "
     << fmt("%.1f", ref.wallPerStepUs) << " us, with the powertrain " << fmt("%.1f", drive.wallPerStepUs)
     << " us (ratio " << fmt("%.2f", drive.wallPerStepUs / ref.wallPerStepUs) << ", one more coordinate and "
     << "the driveline's force laws).\n\n";
  command(md, "assets/scenarios/jturn.toml --vehicle assets/vehicles/sedan_drive.toml");
}

}  // namespace bdfcar::app
