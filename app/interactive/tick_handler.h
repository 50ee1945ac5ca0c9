// What one tick of the interactive loop does, apart from the clock and the
// drawing: read the devices (or the replay), act on the driver's commands
// (pause, single step, reset, rewind, recording, camera, view), advance the
// drive by one driver tick, and say what the HUD should show.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "input/input_system.h"
#include "interactive/draw_thread.h"
#include "render/window.h"
#include "session/drive_session.h"
#include "session/pause_menu.h"

namespace bdfcar::app {

struct InteractiveOptions;

struct TickOutcome {
  bool quit = false;
  ViewCommands view;   // for the drawing thread
};

class TickHandler {
 public:
  TickHandler(DriveSession& session, const InteractiveOptions& options);
  TickOutcome handle(const render::WindowEvents& events);
  // The HUD's message line: a command's effect, a divergence absorbed, pause.
  std::string message() const;
  bool paused() const { return paused_ || menu_.isOpen(); }
  // The pause menu's text while it is open, "" otherwise (the HUD's menu panel).
  std::string menuText() const;
  void setSteeringFeel();
  // The menu's "drive them here": the car and fidelity chosen (the loop ends
  // with it; the caller starts the drive again).
  const std::optional<MenuChoice>& relaunch() const { return relaunch_; }

 private:
  void say(const std::string& text);
  void advance();
  void toggleRecording();
  bool choose(const MenuChoice& choice);

  DriveSession& session_;
  const InteractiveOptions& options_;
  const scenario::CarSteering carSteering_;  // for speed-sensitive steering and a wheel's own angle
  std::unique_ptr<input::InputSystem> devices_;
  bool paused_ = false;
  PauseMenu menu_;
  size_t replayCursor_ = 0;
  std::string message_;
  long messageTicks_ = 0;          // ticks the message stays on screen
  int resetsSeen_ = 0;
  std::optional<MenuChoice> relaunch_;
};

}  // namespace bdfcar::app
