#include "input/controls.h"

namespace bdfcar::input {

// The Controls field that carries `action`.
bool& actionFlag(Controls& controls, Action action) {
  switch (action) {
    case Action::GearUp: return controls.gearUp;
    case Action::GearDown: return controls.gearDown;
    case Action::Reset: return controls.reset;
    case Action::Pause: return controls.pause;
    case Action::SingleStep: return controls.singleStep;
    case Action::Camera: return controls.camera;
    case Action::View: return controls.view;
    case Action::Record: return controls.record;
    case Action::Quit: return controls.quit;
    case Action::Rewind: return controls.rewind;
    case Action::Menu: return controls.menu;
    case Action::MenuUp: return controls.menuUp;
    case Action::MenuDown: return controls.menuDown;
    case Action::MenuSelect: return controls.menuSelect;
  }
  return controls.quit;  // unreachable: the switch covers the enum
}

// Whether `action` fired in `controls`.
bool actionFlag(const Controls& controls, Action action) {
  return actionFlag(const_cast<Controls&>(controls), action);  // reads only
}

// Mapping-file names, in enum order.
constexpr std::string_view kAxisNames[kAxisCount] = {"steering", "throttle", "brake", "clutch", "handbrake"};
constexpr std::string_view kActionNames[kActionCount] = {
    "gear_up", "gear_down", "reset", "pause", "single_step", "camera", "view", "record", "quit", "rewind",
    "menu",    "menu_up",   "menu_down", "menu_select"};
constexpr std::string_view kDeviceKindNames[] = {"keyboard", "wheel", "gamecontroller", "joystick"};

// Mapping-file name of an analog control.
std::string_view axisName(Axis axis) { return kAxisNames[static_cast<int>(axis)]; }

// Mapping-file name of an action.
std::string_view actionName(Action action) { return kActionNames[static_cast<int>(action)]; }

// Mapping-file name of a device kind.
std::string_view deviceKindName(DeviceKind kind) { return kDeviceKindNames[static_cast<int>(kind)]; }

}  // namespace bdfcar::input
