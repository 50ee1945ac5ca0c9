// One 10 ms step of the full vehicle at the paper's setting (BDF2, 2 Newton
// iterations, Jacobian every 200 steps), tyres and terrain rays included,
// with the split Jacobian / residual / back-substitution from the
// integrator's timers. The paper's lane change at 80 km/h: the timed steps
// run from tau = 2 s through the lane change and on straight (10 s, 222 m),
// which keeps the car on the bounded mesh road (a J-turn circle would leave it).
// The car starts in the left lane (y = 1.75 m): clear of curb.toml's block
// and kerb, which would turn the benchmark into a curb strike.
#include <benchmark/benchmark.h>

#include <string>

#include "scenario/scenario_spec.h"
#include "scenario/simulation.h"

using namespace bdfcar;

namespace {

std::string assetPath(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

void stepBenchmark(benchmark::State& st, const std::string& vehicleFile, const std::string& terrainFile) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(assetPath("scenarios/lane_change.toml"));
  spec.vehicleFile = assetPath(vehicleFile);
  spec.terrainFile = terrainFile.empty() ? "" : assetPath(terrainFile);
  spec.settleTime = 0.5;
  spec.startY = 1.75;
  spec.integrator.bdf.timing = true;
  scenario::Simulation sim(spec);
  sim.prepare();
  while (sim.time() < 1.9) sim.step();  // up to the lane change
  const integ::Counters c0 = sim.counters();
  const integ::Timers t0 = sim.timers();
  for (auto _ : st) {
    if (!sim.step().ok()) st.SkipWithError("diverged");
  }
  const integ::Counters& c = sim.counters();
  const integ::Timers& t = sim.timers();
  const double n = static_cast<double>(c.steps - c0.steps);
  st.counters["jacobian_us"] = 1e6 * (t.jacobian - t0.jacobian) / n;
  st.counters["residual_us"] = 1e6 * (t.residual - t0.residual) / n;
  st.counters["backsub_us"] = 1e6 * (t.backSubstitution - t0.backSubstitution) / n;
  st.counters["residuals_per_step"] = static_cast<double>(c.residuals - c0.residuals) / n;
}

void BM_PaperStepFlatRoad(benchmark::State& st) { stepBenchmark(st, "vehicles/paper.toml", "terrain/flat.toml"); }
void BM_PaperStepMeshRoad(benchmark::State& st) { stepBenchmark(st, "vehicles/paper.toml", "terrain/curb.toml"); }
void BM_SedanStepPlane(benchmark::State& st) { stepBenchmark(st, "vehicles/sedan.toml", ""); }
void BM_SedanStepFlatRoad(benchmark::State& st) { stepBenchmark(st, "vehicles/sedan.toml", "terrain/flat.toml"); }
void BM_SedanStepMeshRoad(benchmark::State& st) { stepBenchmark(st, "vehicles/sedan.toml", "terrain/curb.toml"); }
BENCHMARK(BM_PaperStepFlatRoad)->Iterations(1000);
BENCHMARK(BM_PaperStepMeshRoad)->Iterations(1000);
BENCHMARK(BM_SedanStepPlane)->Iterations(1000);
BENCHMARK(BM_SedanStepFlatRoad)->Iterations(1000);
BENCHMARK(BM_SedanStepMeshRoad)->Iterations(1000);

}  // namespace

BENCHMARK_MAIN();
