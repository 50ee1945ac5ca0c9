// The interactive game loop: the driver's tick on the wall clock
// (tick_clock.h), what one tick does (tick_handler.h: devices, commands, one
// driver tick of the drive), and drawing on its own thread at display rate
// from the latest published state (draw_thread.h). Simulated time follows
// wall time whatever the integration step: each tick runs tick / step steps.
#pragma once

#include <optional>
#include <string>

#include "session/drive_session.h"
#include "session/input_recording.h"
#include "session/loop_stats.h"
#include "session/pause_menu.h"

namespace bdfcar::app {

struct InteractiveOptions {
  DriverSource driver = DriverSource::Person;
  const Recording* replay = nullptr;   // with DriverSource::Replay
  std::string mappingDir;              // input mapping files (empty: the shipped ones)
  std::string recordDir = "recordings";  // where F9 puts its numbered recordings
  double seconds = 0;                  // stop after this much wall time (0 = until quit or the end)
  int width = 1280, height = 720;
  bool vsync = true;
  int multisample = -1;  // MSAA samples; -1: 4 on a GPU, none on software GL
  double renderScale = 0;  // the world's resolution (render::WindowOptions); 0: automatic
  bool sound = true;                   // the car's sound on the sound card (audio/), when there is one
  std::string screenshot;              // PNG of the last frame, if set
  bool quitAtEnd = false;              // close when the scenario's duration is reached
  // With quitAtEnd: the closing card (the course's verdict, demo_common.h)
  // held on screen this long before the window closes.
  double closingCardSeconds = 3.0;
  // The cars and fidelities the pause menu offers (none: no such items).
  MenuPicks picks;
  std::string startMessage;  // on the HUD from the first tick (what a relaunch did)
};

// Runs until the person quits, the time limit, or (quitAtEnd) the scenario
// ends. Returns the loop statistics. Throws render::RenderError when no
// window can be opened (the caller falls back to headless). When the person
// chose "drive them here" in the pause menu, *relaunch (if given) holds that
// choice (its car and fidelity indices in options.picks) and the loop has
// ended: the caller starts the drive again at session.place().
LoopStats runInteractive(DriveSession& session, const InteractiveOptions& options,
                         std::optional<MenuChoice>* relaunch = nullptr);

}  // namespace bdfcar::app
