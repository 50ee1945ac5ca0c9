#include "sdl_names.h"

#include <SDL.h>

#include <string>

namespace bdfcar::input::sdl_names {

// Key name -> scancode (scancodes: physical positions, so WASD stays WASD on any layout).
int scancode(std::string_view name) {
  const SDL_Scancode code = SDL_GetScancodeFromName(std::string(name).c_str());
  return code == SDL_SCANCODE_UNKNOWN ? -1 : static_cast<int>(code);
}

// Controller axis name -> SDL_GameControllerAxis.
int controllerAxis(std::string_view name) {
  const SDL_GameControllerAxis axis = SDL_GameControllerGetAxisFromString(std::string(name).c_str());
  return axis == SDL_CONTROLLER_AXIS_INVALID ? -1 : static_cast<int>(axis);
}

// Controller button name -> SDL_GameControllerButton.
int controllerButton(std::string_view name) {
  const SDL_GameControllerButton button = SDL_GameControllerGetButtonFromString(std::string(name).c_str());
  return button == SDL_CONTROLLER_BUTTON_INVALID ? -1 : static_cast<int>(button);
}

// SDL_GameControllerAxis -> its name.
std::string controllerAxisName(int axis) {
  const char* name = SDL_GameControllerGetStringForAxis(static_cast<SDL_GameControllerAxis>(axis));
  return name ? name : "";
}

// SDL_GameControllerButton -> its name.
std::string controllerButtonName(int button) {
  const char* name = SDL_GameControllerGetStringForButton(static_cast<SDL_GameControllerButton>(button));
  return name ? name : "";
}

// SDL reports triggers in 0..32767.
bool isControllerTrigger(int axis) {
  return axis == SDL_CONTROLLER_AXIS_TRIGGERLEFT || axis == SDL_CONTROLLER_AXIS_TRIGGERRIGHT;
}

}  // namespace bdfcar::input::sdl_names
