// The devices a person drives with, polled once per tick. Owns SDL's
// joystick / game-controller / haptic subsystems while it lives; SDL types
// stay inside input/.
//
//   InputSystem input({});                    // loads assets/input/*.toml
//   each 10 ms tick:
//     Controls c = input.poll(0.01);          // events + device state -> plain data
//     ... step the vehicle with c ...
//     input.setSteeringTorque(rackForce / rackForceAtFullFeel);  // optional
//
// poll() takes only keyboard (incl. text-input), joystick and game-controller
// events from SDL's queue (SDL_PeepEvents by type range); window, mouse and
// quit events stay there for whoever owns the window, who must not drain
// those ranges. Keyboard events need an SDL window with focus.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "input/controls.h"
#include "input/mapping.h"

namespace bdfcar::input {

struct InputOptions {
  std::filesystem::path mappingDir = defaultMappingDir();
  // Use only devices whose name contains this (case-insensitive); empty: all.
  std::string deviceFilter;
  // Called (besides spdlog) with each plug / unplug / fallback message.
  std::function<void(const std::string&)> onMessage;
};

// One connected device as the calibration monitor shows it.
struct DeviceStatus {
  int instanceId = -1;                 // SDL joystick instance id
  std::string name;
  DeviceKind kind = DeviceKind::Joystick;  // as its mapping file says
  std::string mappingFile;
  bool forceFeedback = false;          // force feedback opened on it (mapping enables it, device has it)
  bool active = false;                 // it gives the analog controls
  std::vector<int> rawAxes;            // current raw values, -32768..32767
  std::vector<int> pressedButtons;     // indices (controller: SDL button numbers)
};

class InputSystem {
 public:
  // Loads the mapping files and opens every connected device that one fits.
  // Throws MappingError for a bad mapping file, std::runtime_error if SDL fails.
  explicit InputSystem(InputOptions options);
  ~InputSystem();
  InputSystem(const InputSystem&) = delete;
  InputSystem& operator=(const InputSystem&) = delete;

  // This tick's controls: handles plug / unplug, reads the active device,
  // advances the keyboard ramps by dt seconds (dt >= 0), collects the actions.
  Controls poll(double dt);

  // Steering torque command in [-1, 1] (+ = turns the wheel to the left, e.g.
  // the aligning moment over the wheel's felt maximum), sent to the active
  // device's force feedback; nothing happens where there is none.
  void setSteeringTorque(double command);

  // The connected devices with their raw values as of the last poll.
  std::vector<DeviceStatus> devices() const;

  struct State;  // SDL handles and per-device state, defined in input/

 private:
  std::unique_ptr<State> state_;
};

}  // namespace bdfcar::input
