// InputSystem: SDL events and device state -> Controls once per tick, with
// hot-plug, fallback to the keyboard and force feedback.
#include "input/input_system.h"

#include <SDL.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "input/axis_response.h"
#include "input/force_feedback.h"
#include "input/keyboard_ramp.h"
#include "name_match.h"
#include "sdl_device.h"

namespace bdfcar::input {

struct InputSystem::State {
  InputOptions options;
  std::vector<DeviceMapping> mappings;  // fixed for the lifetime: devices point into it
  DeviceMapping keyboard;               // keyboard.toml, or no keys bound
  bool hapticInit = false;
  std::vector<OpenDevice> devices;
  int nextOrder = 0;
  SDL_JoystickID activeId = -1;         // device giving the analog controls; -1: the keyboard
  std::vector<bool> keyHeld = std::vector<bool>(SDL_NUM_SCANCODES, false);
  KeyboardAnalog keyboardAnalog;
  Controls last;
};

namespace {

using State = InputSystem::State;

// Logs a message and hands it to the caller's callback.
void tell(const State& s, spdlog::level::level_enum level, const std::string& message) {
  spdlog::log(level, "input: {}", message);
  if (s.options.onMessage) s.options.onMessage(message);
}

// Who drives when several devices are connected: wheel, then pad, then stick.
int driveRank(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Wheel: return 3;
    case DeviceKind::GameController: return 2;
    case DeviceKind::Joystick: return 1;
    case DeviceKind::Keyboard: return 0;
  }
  return 0;
}

// The open device with this instance id, or nullptr.
OpenDevice* findDevice(State& s, SDL_JoystickID id) {
  for (OpenDevice& d : s.devices)
    if (d.id == id) return &d;
  return nullptr;
}

// Opens a newly connected device index unless filtered out or already open.
void connect(State& s, int index) {
  if (findDevice(s, SDL_JoystickGetDeviceInstanceID(index))) return;  // enumerated and announced by an event
  const char* name = SDL_JoystickNameForIndex(index);
  if (!s.options.deviceFilter.empty() && !containsNoCase(name ? name : "", s.options.deviceFilter)) return;
  OpenResult r = openDevice(index, s.mappings);
  if (r.device.id < 0) {
    tell(s, spdlog::level::warn, r.reason);
    return;
  }
  r.device.order = s.nextOrder++;
  tell(s, spdlog::level::info,
       "connected '" + r.device.name + "' as " + std::string(deviceKindName(r.device.kind)) + " (" +
           r.device.mapping->file + (r.device.haptic.device ? ", force feedback" : "") + ")");
  s.devices.push_back(std::move(r.device));
}

// Closes an unplugged device.
void disconnect(State& s, SDL_JoystickID id) {
  OpenDevice* d = findDevice(s, id);
  if (!d) return;
  tell(s, spdlog::level::warn, "'" + d->name + "' unplugged");
  closeDevice(*d);
  s.devices.erase(s.devices.begin() + (d - s.devices.data()));
}

// Marks the actions bound to `code` in `mapping` as fired this tick; with
// onlyRepeating, those a held key repeats (rewind: held, it keeps going
// back; the menu's up and down: held, they move on).
void fireActions(const DeviceMapping& mapping, int code, Controls& c, bool onlyRepeating = false) {
  for (int a = 0; a < kActionCount; ++a) {
    const Action action = static_cast<Action>(a);
    if (onlyRepeating && action != Action::Rewind && action != Action::MenuUp && action != Action::MenuDown) continue;
    const std::vector<int>& codes = mapping.actions[a];
    if (std::find(codes.begin(), codes.end(), code) != codes.end()) actionFlag(c, static_cast<Action>(a)) = true;
  }
}

// One joystick / controller event: plug, unplug, or a button press.
void handleDeviceEvent(State& s, const SDL_Event& e, Controls& c) {
  switch (e.type) {
    case SDL_JOYDEVICEADDED: connect(s, e.jdevice.which); break;
    case SDL_JOYDEVICEREMOVED: disconnect(s, e.jdevice.which); break;
    case SDL_JOYBUTTONDOWN:  // a controller's buttons count by their controller names below
      if (OpenDevice* d = findDevice(s, e.jbutton.which); d && !d->controller)
        fireActions(*d->mapping, e.jbutton.button, c);
      break;
    case SDL_CONTROLLERBUTTONDOWN:
      if (OpenDevice* d = findDevice(s, e.cbutton.which); d && d->controller)
        fireActions(*d->mapping, e.cbutton.button, c);
      break;
    default: break;  // axis motion: axes are read as state once per tick
  }
}

// One key event: held-key state (pushed events do not update SDL's keyboard state) and actions.
void handleKeyEvent(State& s, const SDL_KeyboardEvent& k, Controls& c) {
  const int code = k.keysym.scancode;
  if (code <= 0 || code >= SDL_NUM_SCANCODES) return;
  s.keyHeld[code] = k.type == SDL_KEYDOWN;
  if (k.type == SDL_KEYDOWN) fireActions(s.keyboard, code, c, k.repeat != 0);
}

// Takes this tick's keyboard and device events from SDL's queue, in order.
void drainEvents(State& s, Controls& c) {
  SDL_PumpEvents();
  SDL_Event events[64];
  int n;
  // Joystick and controller events occupy 0x600..0x6FF; touch events start after them.
  while ((n = SDL_PeepEvents(events, 64, SDL_GETEVENT, SDL_JOYAXISMOTION, SDL_FINGERDOWN - 1)) > 0)
    for (int i = 0; i < n; ++i) handleDeviceEvent(s, events[i], c);
  // The whole keyboard range (0x300..0x3FF): text-input events, which SDL
  // makes by default and nobody here reads, would otherwise fill the queue.
  while ((n = SDL_PeepEvents(events, 64, SDL_GETEVENT, SDL_KEYDOWN, SDL_MOUSEMOTION - 1)) > 0)
    for (int i = 0; i < n; ++i)
      if (events[i].type == SDL_KEYDOWN || events[i].type == SDL_KEYUP) handleKeyEvent(s, events[i].key, c);
}

// The device that should drive now: highest rank, earliest connected; nullptr: keyboard.
const OpenDevice* chooseActive(const State& s) {
  const OpenDevice* best = nullptr;
  for (const OpenDevice& d : s.devices) {
    if (!canDrive(d)) continue;
    if (!best || driveRank(d.kind) > driveRank(best->kind)) best = &d;  // devices are in connection order
  }
  return best;
}

// Switches the driving device if needed; the keyboard takes over from the
// last values and ramps from there instead of jumping.
void updateActive(State& s) {
  const OpenDevice* active = chooseActive(s);
  const SDL_JoystickID id = active ? active->id : -1;
  if (id == s.activeId) return;
  s.activeId = id;
  if (active) {
    tell(s, spdlog::level::info, "driving with '" + active->name + "'");
    return;
  }
  s.keyboardAnalog = {s.last.steering, s.last.throttle, s.last.brake, s.last.clutch, s.last.handbrake};
  tell(s, spdlog::level::warn, "driving with the keyboard");
}

// Whether any of the keys is held.
bool anyHeld(const State& s, const std::vector<int>& keys) {
  return std::any_of(keys.begin(), keys.end(), [&](int k) { return s.keyHeld[k]; });
}

// Analog controls read from a device through its mapping. A pedal reads
// released at and beyond the most released value it has shown (its still
// reading at open, at first), and a pedal axis the device lacks reads released.
void readDevice(OpenDevice& d, Controls& c) {
  double value[kAxisCount] = {};
  for (int i = 0; i < kAxisCount; ++i) {
    const AxisMapping& a = d.mapping->axes[i];
    if (!a.bound || !hasAxis(d, a.axis)) continue;
    const int raw = rawAxis(d, a.axis);
    const Axis control = static_cast<Axis>(i);
    if (control == Axis::Steering) {
      value[i] = axisResponse(a, control, raw);
    } else {
      d.pedalRest[i] = moreReleased(a, d.pedalRest[i], raw);
      value[i] = axisResponse(pedalFromRest(a, d.pedalRest[i]), control, raw);
    }
  }
  c.steering = value[static_cast<int>(Axis::Steering)];
  const AxisMapping& steer = d.mapping->axes[static_cast<int>(Axis::Steering)];
  if (steer.bound && steer.rotationDeg > 0) c.steeringWheelAngle = c.steering * 0.5 * steer.rotationDeg * M_PI / 180.0;
  c.throttle = value[static_cast<int>(Axis::Throttle)];
  c.brake = value[static_cast<int>(Axis::Brake)];
  c.clutch = value[static_cast<int>(Axis::Clutch)];
  c.hasClutch = d.mapping->axes[static_cast<int>(Axis::Clutch)].bound;
  c.handbrake = value[static_cast<int>(Axis::Handbrake)];
  c.speedSensitive = d.mapping->speedSensitive;
  c.source = d.kind;
}

}  // namespace

// Loads mappings, starts SDL's device subsystems, opens connected devices.
InputSystem::InputSystem(InputOptions options) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.options = std::move(options);
  s.mappings = loadMappingDir(s.options.mappingDir);  // before SDL: a bad file leaves nothing to undo
  const auto keyboard = std::find_if(s.mappings.begin(), s.mappings.end(),
                                     [](const DeviceMapping& m) { return m.kind == DeviceKind::Keyboard; });
  if (keyboard != s.mappings.end()) s.keyboard = *keyboard;
  else tell(s, spdlog::level::warn, "no keyboard mapping in " + s.options.mappingDir.string() + "; no keys bound");
  if (SDL_InitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER) != 0)
    throw std::runtime_error(std::string("input: SDL joystick init failed: ") + SDL_GetError());
  s.hapticInit = SDL_InitSubSystem(SDL_INIT_HAPTIC) == 0;  // without it, force feedback is just off
  for (int i = 0; i < SDL_NumJoysticks(); ++i) connect(s, i);
  updateActive(s);
}

// Closes every device and releases the SDL subsystems this object started.
InputSystem::~InputSystem() {
  State& s = *state_;
  for (OpenDevice& d : s.devices) closeDevice(d);
  if (s.hapticInit) SDL_QuitSubSystem(SDL_INIT_HAPTIC);
  SDL_QuitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER);
}

// One tick: events, then the driving device (or the keyboard ramps over dt).
Controls InputSystem::poll(double dt) {
  if (!std::isfinite(dt) || dt < 0.0) throw std::invalid_argument("InputSystem::poll: dt must be finite and >= 0");
  State& s = *state_;
  Controls c;
  drainEvents(s, c);
  updateActive(s);
  const KeyboardKeys& keys = s.keyboard.keys;
  const KeyboardHeld held{anyHeld(s, keys.steerLeft), anyHeld(s, keys.steerRight), anyHeld(s, keys.throttle),
                          anyHeld(s, keys.brake), anyHeld(s, keys.clutch), anyHeld(s, keys.handbrake)};
  s.keyboardAnalog = rampKeyboard(s.keyboard.ramps, held, s.keyboardAnalog, dt);
  if (OpenDevice* d = findDevice(s, s.activeId)) {
    readDevice(*d, c);
  } else {
    c.steering = s.keyboardAnalog.steering;
    c.throttle = s.keyboardAnalog.throttle;
    c.brake = s.keyboardAnalog.brake;
    c.clutch = s.keyboardAnalog.clutch;
    c.hasClutch = !keys.clutch.empty();
    c.handbrake = s.keyboardAnalog.handbrake;
    c.speedSensitive = s.keyboard.speedSensitive;
    c.source = DeviceKind::Keyboard;
  }
  s.last = c;
  return c;
}

// Torque to the driving device's force feedback; other devices are released to 0.
void InputSystem::setSteeringTorque(double command) {
  State& s = *state_;
  for (OpenDevice& d : s.devices)
    setHapticLevel(d.haptic, d.id == s.activeId ? forceFeedbackLevel(d.mapping->forceFeedback, command) : 0);
}

// Connected devices with their current raw values.
std::vector<DeviceStatus> InputSystem::devices() const {
  const State& s = *state_;
  std::vector<DeviceStatus> out;
  for (const OpenDevice& d : s.devices)
    out.push_back({d.id, d.name, d.kind, d.mapping->file, d.haptic.device != nullptr,
                   d.id == s.activeId, rawAxes(d), pressedButtons(d)});
  return out;
}

}  // namespace bdfcar::input
