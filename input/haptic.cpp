#include "haptic.h"

#include <spdlog/spdlog.h>

namespace bdfcar::input {
namespace {

// A constant force along the wheel's axis. SDL directions say where a force
// comes from: from +X (the right) it pushes to the left, our + direction.
SDL_HapticEffect constantForce(int level) {
  SDL_HapticEffect e{};
  e.type = SDL_HAPTIC_CONSTANT;
  e.constant.direction.type = SDL_HAPTIC_CARTESIAN;
  e.constant.direction.dir[0] = 1;
  e.constant.length = SDL_HAPTIC_INFINITY;
  e.constant.level = static_cast<Sint16>(level);
  return e;
}

}  // namespace

// Constant-force effect on a joystick, or nothing.
Haptic openHaptic(SDL_Joystick* joystick, const ForceFeedbackMapping& mapping) {
  Haptic h;
  if (!mapping.enabled || SDL_WasInit(SDL_INIT_HAPTIC) == 0 || SDL_JoystickIsHaptic(joystick) != SDL_TRUE) return h;
  h.device = SDL_HapticOpenFromJoystick(joystick);
  if (!h.device) return h;
  const unsigned int features = SDL_HapticQuery(h.device);
  if (!(features & SDL_HAPTIC_CONSTANT)) {
    closeHaptic(h);
    return h;
  }
  // The tyres' aligning moment already centres the wheel: the device's own spring would double it.
  if (features & SDL_HAPTIC_AUTOCENTER) SDL_HapticSetAutocenter(h.device, 0);
  if (features & SDL_HAPTIC_GAIN) SDL_HapticSetGain(h.device, 100);
  SDL_HapticEffect e = constantForce(0);
  h.effect = SDL_HapticNewEffect(h.device, &e);
  if (h.effect < 0) {
    spdlog::warn("input: force feedback unavailable: {}", SDL_GetError());
    closeHaptic(h);
  }
  return h;
}

// Sends a new level to the running effect (starting it the first time).
void setHapticLevel(Haptic& h, int level) {
  if (!h.device || (h.running && level == h.level)) return;
  SDL_HapticEffect e = constantForce(level);
  if (SDL_HapticUpdateEffect(h.device, h.effect, &e) != 0) return;
  h.level = level;
  if (!h.running) h.running = SDL_HapticRunEffect(h.device, h.effect, 1) == 0;
}

// Releases the effect and the haptic device.
void closeHaptic(Haptic& h) {
  if (!h.device) return;
  if (h.effect >= 0) {
    SDL_HapticStopEffect(h.device, h.effect);
    SDL_HapticDestroyEffect(h.device, h.effect);
  }
  SDL_HapticClose(h.device);
  h = Haptic{};
}

}  // namespace bdfcar::input
