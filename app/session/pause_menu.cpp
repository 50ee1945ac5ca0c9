#include "session/pause_menu.h"

namespace bdfcar::app {

namespace {
// The keys of assets/input/keyboard.toml, for the menu's last lines.
constexpr const char* kKeys =
    "keys:\n"
    "  arrows, WASD  steer, throttle, brake\n"
    "  E / Q  gear up / down     Space  handbrake\n"
    "  Backspace  rewind (held: further back)\n"
    "  R  restart   P  pause   N  step   Esc  quit\n"
    "  C  camera (orbit: drag, mouse wheel)\n"
    "  V  suspension view   F9  record   M  menu";
}  // namespace

PauseMenu::PauseMenu(const std::vector<scenario::Place>& places) {
  items_.push_back({"resume", {MenuChoice::Kind::Resume, -1}});
  items_.push_back({"restart", {MenuChoice::Kind::Restart, -1}});
  for (size_t i = 0; i < places.size(); ++i)
    items_.push_back({"go to: " + places[i].name, {MenuChoice::Kind::GoTo, static_cast<int>(i)}});
  items_.push_back({"quit", {MenuChoice::Kind::Quit, -1}});
}

void PauseMenu::open() {
  open_ = true;
  selected_ = 0;
}

void PauseMenu::up() { selected_ = (selected_ + items() - 1) % items(); }

void PauseMenu::down() { selected_ = (selected_ + 1) % items(); }

MenuChoice PauseMenu::select() {
  open_ = false;
  return items_[selected_].choice;
}

std::string PauseMenu::text() const {
  std::string out = "PAUSED   up / down, Return: choose, M: close\n";
  for (int i = 0; i < items(); ++i) out += (i == selected_ ? "> " : "  ") + items_[i].label + "\n";
  return out + "\n" + kKeys;
}

}  // namespace bdfcar::app
