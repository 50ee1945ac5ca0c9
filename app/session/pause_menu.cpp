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

PauseMenu::PauseMenu(const std::vector<scenario::Place>& places, const MenuPicks& picks) : picks_(picks) {
  items_.push_back({"resume", {MenuChoice::Kind::Resume, -1, -1, -1}, Cycle::None});
  items_.push_back({"restart", {MenuChoice::Kind::Restart, -1, -1, -1}, Cycle::None});
  for (size_t i = 0; i < places.size(); ++i)
    items_.push_back({"go to: " + places[i].name, {MenuChoice::Kind::GoTo, static_cast<int>(i), -1, -1}, Cycle::None});
  if (!picks_.cars.empty() && !picks_.fidelities.empty()) {
    items_.push_back({"car: ", {MenuChoice::Kind::Cycled, -1, -1, -1}, Cycle::Car});
    items_.push_back({"fidelity: ", {MenuChoice::Kind::Cycled, -1, -1, -1}, Cycle::Fidelity});
    items_.push_back({"drive them here (starts again where the car is)", {MenuChoice::Kind::Relaunch, -1, -1, -1}, Cycle::None});
  }
  items_.push_back({"quit", {MenuChoice::Kind::Quit, -1, -1, -1}, Cycle::None});
}

std::string PauseMenu::label(const Item& item) const {
  switch (item.cycle) {
    case Cycle::Car: return item.label + picks_.cars[picks_.car] + "   (Return: next)";
    case Cycle::Fidelity: return item.label + picks_.fidelities[picks_.fidelity] + "   (Return: next)";
    case Cycle::None: break;
  }
  return item.label;
}

void PauseMenu::open() {
  open_ = true;
  selected_ = 0;
}

void PauseMenu::up() { selected_ = (selected_ + items() - 1) % items(); }

void PauseMenu::down() { selected_ = (selected_ + 1) % items(); }

MenuChoice PauseMenu::select() {
  const Item& item = items_[selected_];
  if (item.cycle == Cycle::Car) picks_.car = (picks_.car + 1) % static_cast<int>(picks_.cars.size());
  if (item.cycle == Cycle::Fidelity)
    picks_.fidelity = (picks_.fidelity + 1) % static_cast<int>(picks_.fidelities.size());
  if (item.cycle != Cycle::None) return item.choice;  // stays open
  open_ = false;
  MenuChoice c = item.choice;
  if (c.kind == MenuChoice::Kind::Relaunch) {
    c.car = picks_.car;
    c.fidelity = picks_.fidelity;
  }
  return c;
}

std::string PauseMenu::text() const {
  std::string out = "PAUSED   up / down, Return: choose, M: close\n";
  for (int i = 0; i < items(); ++i) out += (i == selected_ ? "> " : "  ") + label(items_[i]) + "\n";
  return out + "\n" + kKeys;
}

}  // namespace bdfcar::app
