// Mapping files -> DeviceMapping: strict (unknown keys, wrong types and
// out-of-range values are errors at file:line), defaults for what is left out.
#include <sstream>

#include "input/mapping.h"
#include "sdl_names.h"
#include "toml_fields.h"

namespace bdfcar::input {
namespace {

using fields::CodeSpec;
using fields::Range;

constexpr int kRawLo = -32768, kRawHi = 32767;

// The names of all actions, for checkKeys.
std::vector<std::string_view> actionNames() {
  std::vector<std::string_view> names;
  for (int i = 0; i < kActionCount; ++i) names.push_back(actionName(static_cast<Action>(i)));
  return names;
}

// How this kind of device names its axes in a file.
CodeSpec axisSpec(DeviceKind kind) {
  if (kind == DeviceKind::GameController)
    return {0, 0, sdl_names::controllerAxis,
            "an SDL game-controller axis name: leftx, lefty, rightx, righty, lefttrigger, righttrigger"};
  return {0, 255, {}, "an axis index in [0, 255]"};
}

// How this kind of device names its buttons (or keys) in a file.
CodeSpec buttonSpec(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Keyboard:
      return {0, 0, sdl_names::scancode, "an SDL key name such as \"Left\", \"A\", \"Space\", \"F9\""};
    case DeviceKind::GameController:
      return {0, 0, sdl_names::controllerButton,
              "an SDL game-controller button name such as \"a\", \"start\", \"leftshoulder\""};
    default: return {0, 255, {}, "a button index in [0, 255]"};
  }
}

// The TOML document, or a MappingError at the line where the syntax breaks.
toml::value parseToml(const std::string& text, const std::string& fileName) {
  std::istringstream in(text);
  try {
    return toml::parse(in, fileName);
  } catch (const toml::exception& e) {
    throw MappingError(fileName + ":" + std::to_string(e.location().line()) + ": not valid TOML\n" + e.what());
  }
}

// [device]: its type and name filter.
void readDevice(const toml::value& root, DeviceMapping& m) {
  const toml::value& device = *fields::subTable(root, "", "device", true);
  const std::string type =
      fields::readChoice(device, "device", "type", {"keyboard", "wheel", "gamecontroller", "joystick"}, "");
  if (type.empty()) throw MappingError(fields::where(device) + ": table 'device' lacks key 'type'");
  for (DeviceKind k : {DeviceKind::Keyboard, DeviceKind::Wheel, DeviceKind::GameController, DeviceKind::Joystick})
    if (deviceKindName(k) == type) m.kind = k;
  // A keyboard is always there: naming one would be a mistake.
  if (m.kind == DeviceKind::Keyboard) fields::checkKeys(device, "device", {"type"});
  else fields::checkKeys(device, "device", {"type", "name_contains"});
  m.nameContains = fields::readStrings(device, "device", "name_contains");
}

// One [axes.<control>] table.
AxisMapping readAxis(const toml::value& t, const std::string& path, DeviceKind kind) {
  fields::checkKeys(t, path, {"axis", "invert", "deadzone", "gain", "curve", "exponent", "min", "max"});
  AxisMapping a;
  a.bound = true;
  a.axis = fields::readCode(t, path, "axis", axisSpec(kind));
  a.invert = fields::readBool(t, path, "invert", false);
  a.deadzone = fields::readNumber(t, path, "deadzone", Range{0.0, 1.0, false, true}, 0.0);
  a.gain = fields::readNumber(t, path, "gain", Range{0.0, 10.0, true, false}, 1.0);
  a.curve = fields::readChoice(t, path, "curve", {"linear", "power"}, "linear") == "power" ? Curve::Power
                                                                                        : Curve::Linear;
  if (t.contains("exponent") && a.curve != Curve::Power)
    fields::fail(t.at("exponent"), path + ".exponent", "no exponent unless curve = \"power\"");
  a.exponent = fields::readNumber(t, path, "exponent", Range{0.0, 10.0, true, false}, 1.0);
  // Triggers rest at 0, sticks and pedals span the whole raw range.
  const bool trigger = kind == DeviceKind::GameController && sdl_names::isControllerTrigger(a.axis);
  a.rawMin = fields::readInteger(t, path, "min", kRawLo, kRawHi, trigger ? 0 : kRawLo);
  a.rawMax = fields::readInteger(t, path, "max", kRawLo, kRawHi, kRawHi);
  if (a.rawMin == a.rawMax)
    fields::fail(t.contains("max") ? t.at("max") : t.at("min"), path + (t.contains("max") ? ".max" : ".min"),
                 "min and max to differ (they are the calibrated ends of the travel)");
  return a;
}

// [axes]: one table per control the device drives.
void readAxes(const toml::value& root, DeviceMapping& m) {
  const toml::value* axes = fields::subTable(root, "", "axes", false);
  if (!axes) return;
  std::vector<std::string_view> names;
  for (int i = 0; i < kAxisCount; ++i) names.push_back(axisName(static_cast<Axis>(i)));
  fields::checkKeys(*axes, "axes", names);
  for (int i = 0; i < kAxisCount; ++i) {
    const std::string name(names[i]);
    if (const toml::value* t = fields::subTable(*axes, "axes", name, false))
      m.axes[i] = readAxis(*t, "axes." + name, m.kind);
  }
}

// [force_feedback]: present means on unless enabled = false.
void readForceFeedback(const toml::value& root, DeviceMapping& m) {
  const toml::value* ff = fields::subTable(root, "", "force_feedback", false);
  if (!ff) return;
  fields::checkKeys(*ff, "force_feedback", {"enabled", "gain", "invert"});
  m.forceFeedback.enabled = fields::readBool(*ff, "force_feedback", "enabled", true);
  m.forceFeedback.gain = fields::readNumber(*ff, "force_feedback", "gain", Range{0.0, 1.0}, 1.0);
  m.forceFeedback.invert = fields::readBool(*ff, "force_feedback", "invert", false);
}

// [keys] and [ramps] of the keyboard.
void readKeyboard(const toml::value& root, DeviceMapping& m) {
  if (const toml::value* keys = fields::subTable(root, "", "keys", false)) {
    fields::checkKeys(*keys, "keys", {"steer_left", "steer_right", "throttle", "brake", "clutch"});
    const CodeSpec spec = buttonSpec(DeviceKind::Keyboard);
    m.keys.steerLeft = fields::readCodes(*keys, "keys", "steer_left", spec);
    m.keys.steerRight = fields::readCodes(*keys, "keys", "steer_right", spec);
    m.keys.throttle = fields::readCodes(*keys, "keys", "throttle", spec);
    m.keys.brake = fields::readCodes(*keys, "keys", "brake", spec);
    m.keys.clutch = fields::readCodes(*keys, "keys", "clutch", spec);
  }
  if (const toml::value* ramps = fields::subTable(root, "", "ramps", false)) {
    fields::checkKeys(*ramps, "ramps", {"steer_rate", "centre_rate", "pedal_rise_rate", "pedal_fall_rate"});
    const Range rate{0.0, 1000.0, true, false};  // 1/s; > 0 so that every value is reachable
    KeyboardRamps& r = m.ramps;
    r.steerRate = fields::readNumber(*ramps, "ramps", "steer_rate", rate, r.steerRate);
    r.centreRate = fields::readNumber(*ramps, "ramps", "centre_rate", rate, r.centreRate);
    r.pedalRiseRate = fields::readNumber(*ramps, "ramps", "pedal_rise_rate", rate, r.pedalRiseRate);
    r.pedalFallRate = fields::readNumber(*ramps, "ramps", "pedal_fall_rate", rate, r.pedalFallRate);
  }
}

// [actions]: buttons or keys per action.
void readActions(const toml::value& root, DeviceMapping& m) {
  const toml::value* actions = fields::subTable(root, "", "actions", false);
  if (!actions) return;
  const std::vector<std::string_view> names = actionNames();
  fields::checkKeys(*actions, "actions", names);
  for (int i = 0; i < kActionCount; ++i)
    m.actions[i] = fields::readCodes(*actions, "actions", std::string(names[i]), buttonSpec(m.kind));
}

}  // namespace

// One mapping file's text -> DeviceMapping.
DeviceMapping parseMapping(const std::string& text, const std::string& fileName) {
  const toml::value root = parseToml(text, fileName);
  DeviceMapping m;
  m.file = fileName;
  readDevice(root, m);
  if (m.kind == DeviceKind::Keyboard) {
    fields::checkKeys(root, "", {"device", "keys", "ramps", "actions"});
    readKeyboard(root, m);
  } else {
    fields::checkKeys(root, "", {"device", "axes", "actions", "force_feedback"});
    readAxes(root, m);
    readForceFeedback(root, m);
  }
  readActions(root, m);
  return m;
}

}  // namespace bdfcar::input
