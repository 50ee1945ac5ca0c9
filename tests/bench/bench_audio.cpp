// Cost of the car's sound (audio/car_synth.h): one 10 ms tick's 480 samples
// at 48 kHz, on the audio thread (the tick only publishes a SoundState:
// latest_value.h), for the engine alone, the engine with four tyres
// squealing, and everything at once (wind, a shift's and a bump's thumps).
#include <benchmark/benchmark.h>

#include <vector>

#include "audio/car_synth.h"
#include "audio/latest_value.h"

using namespace bdfcar::audio;

namespace {

void renderTicks(benchmark::State& state, SoundState s) {
  CarSynth synth(48000);
  std::vector<float> out(480);
  double rpm = s.engineRpm;
  for (auto _ : state) {
    s.engineRpm = rpm + 0.5 * (state.iterations() % 100);  // the revs moving
    s.shifting = state.iterations() % 50 == 0;
    synth.render(s, out.data(), static_cast<int>(out.size()));
    benchmark::DoNotOptimize(out.data());
  }
}

void BM_SynthEngineTick(benchmark::State& state) { renderTicks(state, {3000, 0.6, 4, 0, {}, {}, false, 0}); }
BENCHMARK(BM_SynthEngineTick);

void BM_SynthEngineAndSquealTick(benchmark::State& state) {
  renderTicks(state, {3000, 0.6, 4, 20, {0.15, 0.15, 0.15, 0.15}, {1, 1, 1, 1}, false, 0});
}
BENCHMARK(BM_SynthEngineAndSquealTick);

void BM_SynthEverythingTick(benchmark::State& state) {
  renderTicks(state, {6000, 1.0, 4, 40, {0.3, 0.3, 0.3, 0.3}, {1, 1, 1, 1}, true, 0.6});
}
BENCHMARK(BM_SynthEverythingTick);

// What the tick pays: publishing a state to the audio thread.
void BM_PublishSoundState(benchmark::State& state) {
  LatestValue<SoundState> latest;
  SoundState s{3000, 0.6, 4, 20, {}, {}, false, 0};
  for (auto _ : state) {
    s.speed += 1e-6;
    latest.publish(s);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_PublishSoundState);

}  // namespace

BENCHMARK_MAIN();
