// The car's sound on the sound card (SDL2 audio): its own thread (SDL's
// callback) renders the synthesiser (car_synth.h) from the newest state the
// physics tick published (latest_value.h: neither waits for the other).
// 48 kHz mono, blocks of 512 samples (10.7 ms, about one tick).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "audio/car_synth.h"
#include "audio/latest_value.h"

namespace bdfcar::audio {

struct AudioError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class AudioOutput {
 public:
  static constexpr int kRate = 48000, kBlock = 512;
  // Opens the default output device; throws AudioError (SDL's reason) when
  // there is none (a machine without a sound card, SDL's dummy driver).
  AudioOutput();
  ~AudioOutput();
  AudioOutput(const AudioOutput&) = delete;
  AudioOutput& operator=(const AudioOutput&) = delete;

  void publish(const SoundState& s) { latest_.publish(s); }  // the tick's: never blocks
  void pause(bool paused);                                   // silence while the drive is paused
  std::string deviceName() const { return name_; }

 private:
  static void callback(void* self, std::uint8_t* stream, int bytes);

  std::uint32_t device_ = 0;  // SDL_AudioDeviceID (no SDL type in this header)
  std::string name_;
  LatestValue<SoundState> latest_;
  SoundState state_;  // the audio thread's
  CarSynth synth_{kRate};
};

}  // namespace bdfcar::audio
