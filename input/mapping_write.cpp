// DeviceMapping -> mapping-file text (what `bdfcar input --calibrate` writes):
// the keys of assets/input/README.md, each number written so that it reads
// back to the same double, defaults left out where a reader can tell them.
#include <charconv>
#include <cstdio>
#include <stdexcept>

#include "input/mapping.h"
#include "sdl_names.h"

namespace bdfcar::input {
namespace {

// The shortest decimal that reads back to x (900, 0.6, 27.77777777777778).
std::string number(double x) {
  char text[32];
  const auto r = std::to_chars(text, text + sizeof text, x);
  return std::string(text, r.ptr);
}

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", c);
      out += escape;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

// One code as the file names it: a game controller's axes and buttons by SDL name, others by index.
std::string code(int value, bool controller, std::string (*name)(int)) {
  return controller ? quoted(name(value)) : std::to_string(value);
}

// `key = [a, b]` of one action's codes, or `key = a`.
std::string codes(const std::vector<int>& values, bool controller) {
  if (values.size() == 1) return code(values[0], controller, sdl_names::controllerButtonName);
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i ? ", " : "") + code(values[i], controller, sdl_names::controllerButtonName);
  return text + "]";
}

// One [axes.<control>] table.
void writeAxis(std::string& out, const AxisMapping& a, Axis control, bool controller) {
  out += "\n[axes." + std::string(axisName(control)) + "]\n";
  out += "axis = " + code(a.axis, controller, sdl_names::controllerAxisName) + "\n";
  if (a.invert) out += "invert = true\n";
  if (a.deadzone != 0.0) out += "deadzone = " + number(a.deadzone) + "\n";
  if (a.curve == Curve::Power) out += "curve = \"power\"\nexponent = " + number(a.exponent) + "\n";
  if (a.gain != 1.0) out += "gain = " + number(a.gain) + "\n";
  out += "min = " + std::to_string(a.rawMin) + "\nmax = " + std::to_string(a.rawMax) + "\n";
  if (control == Axis::Steering && a.rotationDeg > 0) out += "rotation_deg = " + number(a.rotationDeg) + "\n";
}

}  // namespace

// The mapping as its file (see mapping.h).
std::string mappingToml(const DeviceMapping& m, const std::vector<std::string>& comment) {
  if (m.kind == DeviceKind::Keyboard) throw std::invalid_argument("mappingToml: only a device's mapping, not the keyboard's");
  const bool controller = m.kind == DeviceKind::GameController;
  std::string out;
  for (const std::string& line : comment) out += line.empty() ? "#\n" : "# " + line + "\n";
  if (!comment.empty()) out += "\n";
  out += "[device]\ntype = \"" + std::string(deviceKindName(m.kind)) + "\"\nname_contains = [";
  for (std::size_t i = 0; i < m.nameContains.size(); ++i) out += (i ? ", " : "") + quoted(m.nameContains[i]);
  out += "]\n";
  for (int i = 0; i < kAxisCount; ++i)
    if (m.axes[i].bound) writeAxis(out, m.axes[i], static_cast<Axis>(i), controller);
  if (m.speedSensitive.speed > 0)
    out += "\n[speed_sensitive_steering]\nspeed = " + number(m.speedSensitive.speed) + "  # m/s\nscale = " +
           number(m.speedSensitive.scale) + "\n";
  else if (m.speedSensitive.lateralAcceleration > 0)
    out += "\n[speed_sensitive_steering]\nlateral_acceleration = " + number(m.speedSensitive.lateralAcceleration) +
           "  # m/s^2\nscale = " + number(m.speedSensitive.scale) + "\n";
  bool anyAction = false;
  for (int i = 0; i < kActionCount; ++i) {
    if (m.actions[i].empty()) continue;
    if (!anyAction) out += "\n[actions]\n";
    anyAction = true;
    out += std::string(actionName(static_cast<Action>(i))) + " = " + codes(m.actions[i], controller) + "\n";
  }
  if (m.forceFeedback.enabled)
    out += "\n[force_feedback]\ngain = " + number(m.forceFeedback.gain) +
           "\ninvert = " + (m.forceFeedback.invert ? "true" : "false") + "\n";
  return out;
}

}  // namespace bdfcar::input
