// The pause menu of a drive (issue 30): opened and closed with the menu key
// (M; the game controller's guide button), moved through with up / down,
// an item chosen with select. While it is open the drive is paused and the
// other commands wait. Items: resume, restart, one "go to" per place of the
// scene (the scenario's [[places]]: the hill, the skid pad ...), quit; under
// them the keys a driver needs. Plain logic (no window): the tick handler
// acts on its choices, the HUD shows text().
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario_spec.h"

namespace bdfcar::app {

struct MenuChoice {
  enum class Kind { Resume, Restart, GoTo, Quit } kind = Kind::Resume;
  int place = -1;  // GoTo: the index in the scenario's places
};

class PauseMenu {
 public:
  explicit PauseMenu(const std::vector<scenario::Place>& places);

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
  struct Item {
    std::string label;
    MenuChoice choice;
  };
  std::vector<Item> items_;
  int selected_ = 0;
  bool open_ = false;
};

}  // namespace bdfcar::app
