#include "audio/car_synth.h"

#include <algorithm>
#include <cmath>

namespace bdfcar::audio {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kSquealSlip = 0.08;   // combined slip where the squeal starts (past the linear range)
constexpr double kSquealFull = 0.20;   // ... and is at full level
constexpr double kSquealHz[4] = {930, 970, 1010, 1050};  // a little apart per tyre: a chord, not a beat
constexpr double kThumpSeconds = 0.08; // decay time of a shift's or a bump's thump
constexpr double kBumpRate = 0.5;      // m/s of travel rate for a full thump

double lerp(double a, double b, double u) { return a + (b - a) * u; }

// One-pole low-pass coefficient for a cut-off frequency.
double lowPass(double hz, double rate) { return 1.0 - std::exp(-kTwoPi * hz / rate); }

}  // namespace

CarSynth::CarSynth(double sampleRate, std::uint64_t seed) : rate_(sampleRate), rng_(seed | 1) {}

double CarSynth::noise() {
  // xorshift64*: the same noise on every machine.
  rng_ ^= rng_ >> 12;
  rng_ ^= rng_ << 25;
  rng_ ^= rng_ >> 27;
  const std::uint64_t x = rng_ * 0x2545f4914f6cdd1dull;
  return static_cast<double>(x >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

void CarSynth::render(const SoundState& s, float* out, int frames) {
  if (!started_) {
    last_ = s;
    started_ = true;
  }
  const SoundState& a = last_;
  // Events at the start of the block: a shift beginning, a bump.
  if (s.shifting && !a.shifting) {
    thumpAmplitude_ = std::max(thumpAmplitude_, 0.35);
    thumpFrequency_ = 110.0;
  }
  if (s.bump > 0.05) {
    thumpAmplitude_ = std::max(thumpAmplitude_, 0.6 * std::min(1.0, s.bump / kBumpRate));
    thumpFrequency_ = 65.0;
  }
  const double thumpDecay = std::exp(-1.0 / (kThumpSeconds * rate_));
  // The harmonics' levels for the block (the load moves slowly against a
  // 10 ms block): harmonic k of the firing frequency at 1 / k^p, brighter
  // with load.
  double level[kHarmonics + 1];
  const double p = 1.7 - 0.8 * std::clamp(0.5 * (a.engineLoad + s.engineLoad), 0.0, 1.0);
  for (int k = 1; k <= kHarmonics; ++k) level[k] = std::pow(static_cast<double>(k), -p);
  const double windPole = lowPass(900.0, rate_), rollPole = lowPass(180.0, rate_), combustionPole = lowPass(2500.0, rate_);
  for (int i = 0; i < frames; ++i) {
    const double u = frames > 1 ? static_cast<double>(i + 1) / frames : 1.0;
    // Engine: the half order advances at rpm / 60 x cylinders / 4.
    const double rpm = std::max(0.0, lerp(a.engineRpm, s.engineRpm, u));
    const double load = std::clamp(lerp(a.engineLoad, s.engineLoad, u), 0.0, 1.0);
    const double halfOrder = firingFrequency(rpm, s.cylinders) / 2.0;
    enginePhase_ += halfOrder / rate_;
    enginePhase_ -= std::floor(enginePhase_);
    double engine = 0;
    if (rpm > 0) {
      // sin(k x) for k = 1, 2, ... by the recurrence sin((k + 1) x) =
      // 2 cos x sin(k x) - sin((k - 1) x): two trigonometric calls a sample.
      const double x = kTwoPi * 2.0 * enginePhase_, twoCos = 2.0 * std::cos(x);
      double previous = 0.0, current = std::sin(x);
      for (int k = 1; k <= kHarmonics; ++k) {
        if (2.0 * k * halfOrder > 0.45 * rate_) break;  // no aliasing
        engine += level[k] * current;
        const double next = twoCos * current - previous;
        previous = current;
        current = next;
      }
      engine += 0.25 * std::sin(kTwoPi * enginePhase_);  // the half order
      // Combustion noise, pulsed at the firing rate.
      combustionLow_ += combustionPole * (noise() - combustionLow_);
      engine += 0.15 * (0.5 + 0.5 * std::sin(x)) * combustionLow_;
      engine *= (0.25 + 0.75 * load) * std::min(1.0, 0.4 + rpm / 6000.0);
    }
    // Tyres: squeal past the linear range, by load.
    double squeal = 0;
    vibratoPhase_ += 6.0 / rate_;
    vibratoPhase_ -= std::floor(vibratoPhase_);
    for (int w = 0; w < 4; ++w) {
      const double level = std::clamp((lerp(a.slip[w], s.slip[w], u) - kSquealSlip) / (kSquealFull - kSquealSlip), 0.0, 1.0) *
                           std::clamp(lerp(a.load[w], s.load[w], u), 0.0, 1.0);
      const double f = kSquealHz[w] * (1.0 + 0.01 * std::sin(kTwoPi * vibratoPhase_));
      squealPhase_[w] += f / rate_;
      squealPhase_[w] -= std::floor(squealPhase_[w]);
      if (level > 0) squeal += level * (0.8 * std::sin(kTwoPi * squealPhase_[w]) + 0.2 * noise());
    }
    // Wind (speed squared) and rolling (speed) noise.
    const double v = std::abs(lerp(a.speed, s.speed, u));
    windLow_ += windPole * (noise() - windLow_);
    rollLow_ += rollPole * (noise() - rollLow_);
    const double air = std::min(1.0, (v / 45.0) * (v / 45.0)) * 0.8 * windLow_ + std::min(1.0, v / 40.0) * 1.2 * rollLow_;
    // The thump of a shift or a bump.
    thumpPhase_ += thumpFrequency_ / rate_;
    thumpPhase_ -= std::floor(thumpPhase_);
    const double thump = thumpAmplitude_ * std::sin(kTwoPi * thumpPhase_);
    thumpAmplitude_ *= thumpDecay;
    // Mixed and softly limited (never clipped hard).
    out[i] = static_cast<float>(std::tanh(0.45 * engine + 0.25 * squeal + 0.3 * air + thump));
  }
  last_ = s;
}

}  // namespace bdfcar::audio
