// Mapping files (assets/input/*.toml) as plain data: which device a file is
// for, how each axis becomes a control, which buttons / keys fire which
// actions, the keyboard's ramp rates and the force-feedback settings.
// The file format is described in assets/input/README.md.
#pragma once

#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "input/controls.h"

namespace bdfcar::input {

// A mapping file that cannot be used; what() starts with "file:line: ".
struct MappingError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Curve { Linear, Power };

// How one raw SDL axis value (-32768..32767) becomes one control.
struct AxisMapping {
  bool bound = false;    // false: this device does not drive the control
  int axis = 0;          // joystick axis index, or SDL game-controller axis number
  bool invert = false;   // steering: x -> -x; pedals: x -> 1 - x
  double deadzone = 0.0; // [0, 1): |x| below it reads 0; the rest is rescaled to reach 1
  double gain = 1.0;     // (0, 10]: output = gain * curve(x), clamped to the control's range
  Curve curve = Curve::Linear;
  double exponent = 1.0; // curve = Power: curve(x) = x^exponent
  int rawMin = -32768;   // calibrated raw value at full left (steering) or pedal released
  int rawMax = 32767;    // calibrated raw value at full right (steering) or pedal fully down
  // Steering only: the wheel's rotation from lock to lock (a 900 degree
  // wheel: 900), so that its angle turns the car's steering wheel by as
  // much (controls.h, steeringWheelAngle). 0: not given (full input = full lock).
  double rotationDeg = 0.0;
};

// Constant-force steering torque through SDL haptic, if the device has it.
struct ForceFeedbackMapping {
  bool enabled = false;
  double gain = 1.0;     // [0, 1], fraction of the device's full force at command 1
  bool invert = false;   // for wheels whose motor turns the other way
};

// Keys that drive the analog controls (SDL scancode numbers).
struct KeyboardKeys {
  std::vector<int> steerLeft, steerRight, throttle, brake, clutch, handbrake;
};

// Keyboard ramp rates in 1/s: no bang-bang steering or pedals.
struct KeyboardRamps {
  double steerRate = 2.0;      // towards full lock while a steer key is held (0 -> 1 in 0.5 s)
  double centreRate = 2.0;     // back towards 0 when no steer key (or both) is held
  double pedalRiseRate = 5.0;  // pedal 0 -> 1 in 0.2 s while its key is held
  double pedalFallRate = 5.0;  // pedal back to 0 after release
};

struct DeviceMapping {
  std::string file;                      // where it came from, for messages
  DeviceKind kind = DeviceKind::Keyboard;
  std::vector<std::string> nameContains; // case-insensitive; empty: any device of this kind

  // Wheel, game controller, joystick.
  std::array<AxisMapping, kAxisCount> axes{};  // indexed by Axis
  ForceFeedbackMapping forceFeedback;

  // Keyboard.
  KeyboardKeys keys;
  KeyboardRamps ramps;

  // Any device, the keyboard included: off unless the file has the table.
  SpeedSensitiveSteering speedSensitive;

  // Per Action: button indices (joystick, wheel), SDL game-controller button
  // numbers, or key scancodes (keyboard).
  std::array<std::vector<int>, kActionCount> actions{};
};

// Parses one mapping file's text; fileName is used in error messages only.
DeviceMapping parseMapping(const std::string& text, const std::string& fileName);

// A device's mapping (wheel, game controller, joystick; not the keyboard's
// keys and ramps) as mapping-file text that parseMapping reads back to the same
// values: `comment` (lines) first as # comments, then [device], the bound
// [axes.*], [speed_sensitive_steering], [actions] and [force_feedback].
std::string mappingToml(const DeviceMapping& mapping, const std::vector<std::string>& comment);

// Reads and parses one mapping file.
DeviceMapping loadMappingFile(const std::filesystem::path& path);

// Every *.toml file of a folder, sorted by file name (the order breaks ties in matching).
std::vector<DeviceMapping> loadMappingDir(const std::filesystem::path& dir);

// assets/input of the source tree this library was built from.
std::filesystem::path defaultMappingDir();

// The index of the mapping that best fits a connected device, or -1 for none.
// A name-specific file beats a generic one; within the joystick family a file
// of the exact kind beats a "joystick" one, and a name-specific "wheel" file
// also claims a device SDL only calls a joystick (many wheels on Linux).
int matchMapping(const std::vector<DeviceMapping>& mappings, DeviceKind kind, std::string_view deviceName);

}  // namespace bdfcar::input
