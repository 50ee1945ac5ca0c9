#include "audio/audio_output.h"

#include <SDL.h>

namespace bdfcar::audio {

AudioOutput::AudioOutput() {
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) throw AudioError(std::string("no audio: ") + SDL_GetError());
  SDL_AudioSpec want{}, have{};
  want.freq = kRate;
  want.format = AUDIO_F32SYS;
  want.channels = 1;
  want.samples = kBlock;
  want.callback = &AudioOutput::callback;
  want.userdata = this;
  device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);  // exactly as asked: SDL converts
  if (device_ == 0) {
    const std::string why = SDL_GetError();
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    throw AudioError("no sound device: " + why);
  }
  const char* driver = SDL_GetCurrentAudioDriver();
  name_ = driver ? driver : "?";
  SDL_PauseAudioDevice(device_, 0);
}

AudioOutput::~AudioOutput() {
  SDL_CloseAudioDevice(device_);  // waits for the callback to return
  SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void AudioOutput::pause(bool paused) { SDL_PauseAudioDevice(device_, paused ? 1 : 0); }

void AudioOutput::callback(void* self, std::uint8_t* stream, int bytes) {
  auto* out = static_cast<AudioOutput*>(self);
  out->latest_.take(out->state_);  // the newest state, or the last one again
  out->synth_.render(out->state_, reinterpret_cast<float*>(stream), bytes / static_cast<int>(sizeof(float)));
}

}  // namespace bdfcar::audio
