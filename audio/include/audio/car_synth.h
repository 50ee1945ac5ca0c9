// The car's sound, synthesised (no recorded samples): deterministic, mono,
// at any sample rate, one block per driver tick, the parameters ramped over
// the block from the last tick's to this one's so that nothing clicks.
//
//  - Engine: the harmonics of the firing frequency (the fundamental of a
//    four-stroke's exhaust note, rpm / 60 x cylinders / 2) and its half
//    order (the crank's own rotation, which an uneven firing gives), their
//    spectrum brighter with load (the upper harmonics rise as the pressure
//    pulses sharpen), with combustion noise pulsed at the firing rate;
//    louder with load and speed.
//  - Tyres: squeal past the slip where a tyre leaves its linear range (a
//    tone near 1 kHz, vibrato and noise), per tyre, weighted by its load.
//  - Wind (low-passed noise, as the square of speed) and rolling noise
//    (lower, as speed).
//  - A gear shift's clunk and a bump's thump: decaying low tones started
//    when the shift begins or a wheel's travel rate jumps.
#pragma once

#include <cstdint>

#include "audio/sound_state.h"

namespace bdfcar::audio {

class CarSynth {
 public:
  static constexpr int kHarmonics = 8;
  explicit CarSynth(double sampleRate, std::uint64_t seed = 0x9e3779b97f4a7c15ull);

  // `frames` mono samples in [-1, 1] from the last state given to `s`.
  void render(const SoundState& s, float* out, int frames);
  double sampleRate() const { return rate_; }

 private:
  double noise();  // white, [-1, 1], deterministic

  double rate_;
  std::uint64_t rng_;
  SoundState last_;
  bool started_ = false;
  double enginePhase_ = 0;  // of the half order (cycles): harmonic k of the firing frequency is 2 k times it
  double squealPhase_[4] = {0, 0, 0, 0};
  double vibratoPhase_ = 0;
  double windLow_ = 0, rollLow_ = 0, combustionLow_ = 0;
  double thumpPhase_ = 0, thumpAmplitude_ = 0, thumpFrequency_ = 0;
};

}  // namespace bdfcar::audio
