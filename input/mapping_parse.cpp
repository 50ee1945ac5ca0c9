// Mapping files -> DeviceMapping: strict (unknown keys, wrong types and
// out-of-range values are errors at file:line), defaults for what is left out.
// The TOML is read through config::Table; its ConfigError becomes MappingError.
#include <functional>
#include <optional>
#include <string_view>

#include "config/toml_reader.h"
#include "input/mapping.h"
#include "sdl_names.h"

namespace bdfcar::input {
namespace {

using config::Range;
using config::Table;

constexpr int kRawLo = -32768, kRawHi = 32767;
constexpr long kMaxIndex = 255;  // joystick axes and buttons are numbered 0..255

// How a file names buttons / keys / axes: by index in [0, kMaxIndex], or
// (fromName set) by a name that fromName resolves to a code (-1: no such name).
struct CodeSpec {
  std::function<int(std::string_view)> fromName;
  std::string expected;  // the accepted names, e.g. "an SDL key name such as \"Left\""
};

// The names of all actions, for rejectUnknownKeys.
std::vector<std::string_view> actionNames() {
  std::vector<std::string_view> names;
  for (int i = 0; i < kActionCount; ++i) names.push_back(actionName(static_cast<Action>(i)));
  return names;
}

// How this kind of device names its axes in a file.
CodeSpec axisSpec(DeviceKind kind) {
  if (kind == DeviceKind::GameController)
    return {sdl_names::controllerAxis,
            "an SDL game-controller axis name: leftx, lefty, rightx, righty, lefttrigger, righttrigger"};
  return {};
}

// How this kind of device names its buttons (or keys) in a file.
CodeSpec buttonSpec(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Keyboard: return {sdl_names::scancode, "an SDL key name such as \"Left\", \"A\", \"Space\", \"F9\""};
    case DeviceKind::GameController:
      return {sdl_names::controllerButton, "an SDL game-controller button name such as \"a\", \"start\", \"leftshoulder\""};
    default: return {};
  }
}

// A required code (index or name) per spec.
int readCode(Table& t, const std::string& key, const CodeSpec& spec) {
  if (!spec.fromName) return static_cast<int>(t.integerIn(key, 0, kMaxIndex));
  const int code = t.isString(key) ? spec.fromName(t.string(key)) : -1;
  if (code < 0) t.reject(key, spec.expected);
  return code;
}

// An optional code or array of codes per spec; none when absent.
std::vector<int> readCodes(Table& t, const std::string& key, const CodeSpec& spec) {
  std::vector<int> codes;
  if (!spec.fromName) {
    for (long index : t.integersIn(key, 0, kMaxIndex)) codes.push_back(static_cast<int>(index));
    return codes;
  }
  const std::vector<std::string> names = t.stringOrStrings(key);
  for (std::size_t i = 0; i < names.size(); ++i) {
    codes.push_back(spec.fromName(names[i]));
    if (codes.back() < 0) t.reject(key, spec.expected, t.isArray(key) ? static_cast<int>(i) : -1);
  }
  return codes;
}

// [device]: its type and name filter.
void readDevice(Table& root, DeviceMapping& m) {
  Table device = root.table("device");
  const std::string type = device.choice("type", {"keyboard", "wheel", "gamecontroller", "joystick"});
  for (DeviceKind k : {DeviceKind::Keyboard, DeviceKind::Wheel, DeviceKind::GameController, DeviceKind::Joystick})
    if (deviceKindName(k) == type) m.kind = k;
  // A keyboard is always there: naming one would be a mistake.
  if (m.kind == DeviceKind::Keyboard) device.rejectUnknownKeys({"type"});
  else device.rejectUnknownKeys({"type", "name_contains"});
  m.nameContains = device.stringOrStrings("name_contains");
}

// One [axes.<control>] table.
AxisMapping readAxis(Table& t, DeviceKind kind, Axis control) {
  if (control == Axis::Steering)
    t.rejectUnknownKeys({"axis", "invert", "deadzone", "gain", "curve", "exponent", "min", "max", "rotation_deg"});
  else
    t.rejectUnknownKeys({"axis", "invert", "deadzone", "gain", "curve", "exponent", "min", "max"});
  AxisMapping a;
  a.bound = true;
  a.axis = readCode(t, "axis", axisSpec(kind));
  a.invert = t.boolean("invert", false);
  a.deadzone = t.numberIn("deadzone", Range{0.0, 1.0, false, true}, 0.0);
  a.gain = t.numberIn("gain", Range{0.0, 10.0, true, false}, 1.0);
  a.curve = t.choice("curve", {"linear", "power"}, "linear") == "power" ? Curve::Power : Curve::Linear;
  if (t.has("exponent") && a.curve != Curve::Power) t.reject("exponent", "no exponent unless curve = \"power\"");
  a.exponent = t.numberIn("exponent", Range{0.0, 10.0, true, false}, 1.0);
  if (control == Axis::Steering) a.rotationDeg = t.numberIn("rotation_deg", Range{0.0, 3600.0, true, false}, 0.0);
  // Triggers rest at 0, sticks and pedals span the whole raw range.
  const bool trigger = kind == DeviceKind::GameController && sdl_names::isControllerTrigger(a.axis);
  a.rawMin = static_cast<int>(t.integerIn("min", kRawLo, kRawHi, trigger ? 0 : kRawLo));
  a.rawMax = static_cast<int>(t.integerIn("max", kRawLo, kRawHi, kRawHi));
  if (a.rawMin == a.rawMax)
    t.reject(t.has("max") ? "max" : "min", "min and max to differ (they are the calibrated ends of the travel)");
  return a;
}

// [axes]: one table per control the device drives.
void readAxes(Table& root, DeviceMapping& m) {
  std::optional<Table> axes = root.optionalTable("axes");
  if (!axes) return;
  std::vector<std::string_view> names;
  for (int i = 0; i < kAxisCount; ++i) names.push_back(axisName(static_cast<Axis>(i)));
  axes->rejectUnknownKeys(names);
  for (int i = 0; i < kAxisCount; ++i)
    if (std::optional<Table> t = axes->optionalTable(std::string(names[i]))) m.axes[i] = readAxis(*t, m.kind, static_cast<Axis>(i));
}

// [force_feedback]: present means on unless enabled = false.
void readForceFeedback(Table& root, DeviceMapping& m) {
  std::optional<Table> ff = root.optionalTable("force_feedback");
  if (!ff) return;
  ff->rejectUnknownKeys({"enabled", "gain", "invert"});
  m.forceFeedback.enabled = ff->boolean("enabled", true);
  m.forceFeedback.gain = ff->numberIn("gain", Range{0.0, 1.0}, 1.0);
  m.forceFeedback.invert = ff->boolean("invert", false);
}

// [speed_sensitive_steering]: present means on.
void readSpeedSensitiveSteering(Table& root, DeviceMapping& m) {
  std::optional<Table> t = root.optionalTable("speed_sensitive_steering");
  if (!t) return;
  t->rejectUnknownKeys({"speed", "scale", "lateral_acceleration"});
  // The linear law (speed) or the grip law (lateral_acceleration), one of them.
  if (t->has("speed") && t->has("lateral_acceleration"))
    t->fail("give 'speed' (the linear law) or 'lateral_acceleration' (the grip law), not both", "lateral_acceleration");
  if (!t->has("speed") && !t->has("lateral_acceleration"))
    t->fail("expected 'speed' (the linear law) or 'lateral_acceleration' (the grip law)");
  // Up to 200 m/s (720 km/h) and 50 m/s^2 (5 g): more is a typo; the scale must leave some steering.
  if (t->has("speed"))
    m.speedSensitive.speed = t->number("speed", config::Dimension::Speed, Range{0.0, 200.0, true, false});
  else
    m.speedSensitive.lateralAcceleration =
        t->number("lateral_acceleration", config::Dimension::Acceleration, Range{0.0, 50.0, true, false});
  m.speedSensitive.scale = t->numberIn("scale", Range{0.0, 1.0, true, false});
}

// [keys] and [ramps] of the keyboard.
void readKeyboard(Table& root, DeviceMapping& m) {
  if (std::optional<Table> keys = root.optionalTable("keys")) {
    keys->rejectUnknownKeys({"steer_left", "steer_right", "throttle", "brake", "clutch", "handbrake"});
    const CodeSpec spec = buttonSpec(DeviceKind::Keyboard);
    m.keys.steerLeft = readCodes(*keys, "steer_left", spec);
    m.keys.steerRight = readCodes(*keys, "steer_right", spec);
    m.keys.throttle = readCodes(*keys, "throttle", spec);
    m.keys.brake = readCodes(*keys, "brake", spec);
    m.keys.clutch = readCodes(*keys, "clutch", spec);
    m.keys.handbrake = readCodes(*keys, "handbrake", spec);
  }
  if (std::optional<Table> ramps = root.optionalTable("ramps")) {
    ramps->rejectUnknownKeys({"steer_rate", "centre_rate", "pedal_rise_rate", "pedal_fall_rate"});
    const Range rate{0.0, 1000.0, true, false};  // 1/s; > 0 so that every value is reachable
    KeyboardRamps& r = m.ramps;
    r.steerRate = ramps->numberIn("steer_rate", rate, r.steerRate);
    r.centreRate = ramps->numberIn("centre_rate", rate, r.centreRate);
    r.pedalRiseRate = ramps->numberIn("pedal_rise_rate", rate, r.pedalRiseRate);
    r.pedalFallRate = ramps->numberIn("pedal_fall_rate", rate, r.pedalFallRate);
  }
}

// [actions]: buttons or keys per action.
void readActions(Table& root, DeviceMapping& m) {
  std::optional<Table> actions = root.optionalTable("actions");
  if (!actions) return;
  const std::vector<std::string_view> names = actionNames();
  actions->rejectUnknownKeys(names);
  for (int i = 0; i < kActionCount; ++i) m.actions[i] = readCodes(*actions, std::string(names[i]), buttonSpec(m.kind));
}

DeviceMapping readMapping(Table root, const std::string& fileName) {
  DeviceMapping m;
  m.file = fileName;
  readDevice(root, m);
  if (m.kind == DeviceKind::Keyboard) {
    root.rejectUnknownKeys({"device", "keys", "ramps", "actions", "speed_sensitive_steering"});
    readKeyboard(root, m);
  } else {
    root.rejectUnknownKeys({"device", "axes", "actions", "force_feedback", "speed_sensitive_steering"});
    readAxes(root, m);
    readForceFeedback(root, m);
  }
  readSpeedSensitiveSteering(root, m);
  readActions(root, m);
  return m;
}

}  // namespace

// One mapping file's text -> DeviceMapping; the reader's "file:line: ..." message is kept as is.
DeviceMapping parseMapping(const std::string& text, const std::string& fileName) {
  try {
    return readMapping(config::parseTomlText(text, fileName), fileName);
  } catch (const config::ConfigError& e) {
    throw MappingError(e.what());
  }
}

}  // namespace bdfcar::input
