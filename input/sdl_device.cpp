#include "sdl_device.h"

namespace bdfcar::input {

// Wheel if SDL types it so (a wheel is never a game controller), else controller, else joystick.
DeviceKind classifyDevice(int index) {
  if (SDL_JoystickGetDeviceType(index) == SDL_JOYSTICK_TYPE_WHEEL) return DeviceKind::Wheel;
  if (SDL_IsGameController(index)) return DeviceKind::GameController;
  return DeviceKind::Joystick;
}

// Opens the device through the API its mapping's kind uses.
OpenResult openDevice(int index, const std::vector<DeviceMapping>& mappings) {
  OpenResult r;
  const char* sdlName = SDL_JoystickNameForIndex(index);
  const std::string name = sdlName ? sdlName : "(unnamed)";
  const int m = matchMapping(mappings, classifyDevice(index), name);
  if (m < 0) {
    r.reason = "'" + name + "' (" + std::string(deviceKindName(classifyDevice(index))) +
               ") fits no mapping file; ignored";
    return r;
  }
  OpenDevice d;
  d.mapping = &mappings[m];
  d.kind = d.mapping->kind;
  d.name = name;
  if (d.kind == DeviceKind::GameController) {
    d.controller = SDL_GameControllerOpen(index);
    d.joystick = d.controller ? SDL_GameControllerGetJoystick(d.controller) : nullptr;
  } else {
    d.joystick = SDL_JoystickOpen(index);
  }
  if (!d.joystick) {
    r.reason = "cannot open '" + name + "': " + SDL_GetError();
    return r;
  }
  d.id = SDL_JoystickInstanceID(d.joystick);
  d.haptic = openHaptic(d.joystick, d.mapping->forceFeedback);
  // A device's axes read 0 until SDL first updates it: the still reading comes after one update.
  SDL_JoystickUpdate();
  for (int i = 0; i < kAxisCount; ++i) {
    const AxisMapping& a = d.mapping->axes[i];
    if (static_cast<Axis>(i) != Axis::Steering && a.bound && hasAxis(d, a.axis)) d.pedalRest[i] = rawAxis(d, a.axis);
  }
  r.device = std::move(d);
  return r;
}

// Releases the device's SDL handles.
void closeDevice(OpenDevice& d) {
  closeHaptic(d.haptic);
  if (d.controller) SDL_GameControllerClose(d.controller);
  else if (d.joystick) SDL_JoystickClose(d.joystick);
  d.controller = nullptr;
  d.joystick = nullptr;
}

// Current raw value of an axis as the mapping numbers it.
int rawAxis(const OpenDevice& d, int axis) {
  if (d.controller) return SDL_GameControllerGetAxis(d.controller, static_cast<SDL_GameControllerAxis>(axis));
  return SDL_JoystickGetAxis(d.joystick, axis);
}

// The controller API knows its axes by name; a joystick numbers them from 0.
bool hasAxis(const OpenDevice& d, int axis) {
  if (d.controller) return SDL_GameControllerHasAxis(d.controller, static_cast<SDL_GameControllerAxis>(axis));
  return axis >= 0 && axis < SDL_JoystickNumAxes(d.joystick);
}

// Steering bound to an axis that exists (a button box fitting a generic file cannot drive).
bool canDrive(const OpenDevice& d) {
  const AxisMapping& steering = d.mapping->axes[static_cast<int>(Axis::Steering)];
  return steering.bound && hasAxis(d, steering.axis);
}

// All raw axis values.
std::vector<int> rawAxes(const OpenDevice& d) {
  const int n = d.controller ? static_cast<int>(SDL_CONTROLLER_AXIS_MAX) : SDL_JoystickNumAxes(d.joystick);
  std::vector<int> values;
  for (int i = 0; i < n; ++i) values.push_back(rawAxis(d, i));
  return values;
}

// Indices of the buttons held now.
std::vector<int> pressedButtons(const OpenDevice& d) {
  std::vector<int> held;
  if (d.controller) {
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b)
      if (SDL_GameControllerGetButton(d.controller, static_cast<SDL_GameControllerButton>(b))) held.push_back(b);
  } else {
    for (int b = 0; b < SDL_JoystickNumButtons(d.joystick); ++b)
      if (SDL_JoystickGetButton(d.joystick, b)) held.push_back(b);
  }
  return held;
}

}  // namespace bdfcar::input
