// SDL haptic for steering-wheel force feedback: one constant-force effect
// whose level follows the caller's torque command (private to input/).
#pragma once

#include <SDL.h>

#include "input/mapping.h"

namespace bdfcar::input {

struct Haptic {
  SDL_Haptic* device = nullptr;  // nullptr: no force feedback on this device
  int effect = -1;
  int level = 0;                 // last level sent
  bool running = false;
};

// Opens a constant-force effect on a joystick if the mapping enables it and
// the device can do it; an empty Haptic otherwise (silently: most devices cannot).
Haptic openHaptic(SDL_Joystick* joystick, const ForceFeedbackMapping& mapping);

// Sets the effect's level in [-32767, 32767] (sent only when it changes).
void setHapticLevel(Haptic& haptic, int level);

// Stops the effect and closes the device.
void closeHaptic(Haptic& haptic);

}  // namespace bdfcar::input
