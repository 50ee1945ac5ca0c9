// One connected SDL joystick / wheel / game controller with the mapping file
// it uses (private to input/).
#pragma once

#include <SDL.h>

#include <array>
#include <string>
#include <vector>

#include "haptic.h"
#include "input/controls.h"
#include "input/mapping.h"

namespace bdfcar::input {

struct OpenDevice {
  SDL_JoystickID id = -1;
  SDL_Joystick* joystick = nullptr;          // owned unless `controller` is set (then it is the controller's)
  SDL_GameController* controller = nullptr;  // game controllers only
  const DeviceMapping* mapping = nullptr;
  DeviceKind kind = DeviceKind::Joystick;    // the mapping's kind
  std::string name;
  int order = 0;                             // connection order, breaks ties between equal devices
  Haptic haptic;
  // Per control (Axis), pedals only: the most released raw reading of its axis
  // since the device was opened, starting from the still reading at open, at
  // and beyond which the pedal reads released (axis_response.h, pedalFromRest).
  std::array<int, kAxisCount> pedalRest{};
};

// Result of trying to open a device: `device.id < 0` when it was not opened, with the reason.
struct OpenResult {
  OpenDevice device;
  std::string reason;
};

// SDL's view of what a device index is, before any mapping.
DeviceKind classifyDevice(int deviceIndex);

// Opens a device index with the mapping that fits it best.
OpenResult openDevice(int deviceIndex, const std::vector<DeviceMapping>& mappings);

// Closes force feedback, then the device.
void closeDevice(OpenDevice& device);

// Raw value of one axis (joystick index or controller axis, per the mapping's kind).
int rawAxis(const OpenDevice& device, int axis);

// Whether the device has that axis (SDL reads a missing one as 0, mid-range).
bool hasAxis(const OpenDevice& device, int axis);

// Whether the device can drive: its mapping binds steering to an axis it has.
bool canDrive(const OpenDevice& device);

// Raw values of all axes, and the buttons held now (for the calibration monitor).
std::vector<int> rawAxes(const OpenDevice& device);
std::vector<int> pressedButtons(const OpenDevice& device);

}  // namespace bdfcar::input
