// The pause menu of a drive (issue 30): opened and closed with the menu key
// (M; the game controller's guide button), moved through with up / down,
// an item chosen with select. While it is open the drive is paused and the
// other commands wait. Items: resume, restart, one "go to" per place of the
// scene (the scenario's [[places]]: the hill, the skid pad ...), where the
// drive offers them the car and the fidelity (each chosen by selecting it
// again and again: it cycles, the menu stays open) and "drive them here"
// (the drive starts again at the place it is at, with that car on that
// rung), quit; under them the keys a driver needs. Plain logic (no window):
// the tick handler acts on its choices, the HUD shows text().
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario_spec.h"

namespace bdfcar::app {

struct MenuChoice {
  // Cycled: a car or fidelity item moved to its next value (the menu stays
  // open); Relaunch: drive the chosen car and fidelity here.
  enum class Kind { Resume, Restart, GoTo, Cycled, Relaunch, Quit } kind = Kind::Resume;
  int place = -1;     // GoTo: the index in the scenario's places
  int car = -1;       // Relaunch: the indices in MenuPicks' lists
  int fidelity = -1;
};

// The cars and fidelities the menu offers, the current ones first chosen
// (no cars: no such items).
struct MenuPicks {
  std::vector<std::string> cars;        // labels (the vehicle files' names)
  std::vector<std::string> fidelities;  // the ladder's rungs and auto
  int car = 0, fidelity = 0;
};

class PauseMenu {
 public:
  explicit PauseMenu(const std::vector<scenario::Place>& places, const MenuPicks& picks = {});

  bool isOpen() const { return open_; }
  void open();   // at its first item
  void close() { open_ = false; }
  void up();     // wraps round
  void down();
  // The highlighted item as a choice; the menu closes.
  MenuChoice select();
  int selected() const { return selected_; }
  int items() const { return static_cast<int>(items_.size()); }
  // What the HUD shows while it is open: the items, the highlighted one
  // marked, and the keys.
  std::string text() const;

 private:
  enum class Cycle { None, Car, Fidelity };
  struct Item {
    std::string label;
    MenuChoice choice;
    Cycle cycle = Cycle::None;
  };
  std::string label(const Item& item) const;
  std::vector<Item> items_;
  MenuPicks picks_;
  int selected_ = 0;
  bool open_ = false;
};

}  // namespace bdfcar::app
