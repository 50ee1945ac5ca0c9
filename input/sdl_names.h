// SDL's names for keys and game-controller axes / buttons, as plain ints
// (private to input/: the parser resolves names without exposing SDL types).
#pragma once

#include <string>
#include <string_view>

namespace bdfcar::input::sdl_names {

// SDL scancode of a key name such as "Left", "A", "Space", "F9"; -1 if unknown.
int scancode(std::string_view name);

// SDL game-controller axis of a name such as "leftx", "righttrigger"; -1 if unknown.
int controllerAxis(std::string_view name);

// SDL game-controller button of a name such as "a", "start", "leftshoulder"; -1 if unknown.
int controllerButton(std::string_view name);

// SDL's names of a game-controller axis / button (what the two functions above
// read back); "" if there is none.
std::string controllerAxisName(int axis);
std::string controllerButtonName(int button);

// Whether a game-controller axis is a trigger (reads 0..32767 instead of -32768..32767).
bool isControllerTrigger(int axis);

}  // namespace bdfcar::input::sdl_names
