// The interactive game loop: physics on a fixed 10 ms tick at absolute
// deadlines (sleep, then a short spin) with capped catch-up, input polled
// once per tick, on the main thread (SDL's events belong there); drawing on a
// render thread at display rate from the latest published state. Pause,
// single step, reset, camera and view switches, input recording; loop
// statistics at exit.
#pragma once

#include <optional>
#include <string>

#include "session/drive_session.h"
#include "session/input_recording.h"
#include "session/loop_stats.h"

namespace bdfcar::app {

struct InteractiveOptions {
  DriverSource driver = DriverSource::Person;
  const Recording* replay = nullptr;   // with DriverSource::Replay
  double seconds = 0;                  // stop after this much wall time (0 = until quit or the end)
  int width = 1280, height = 720;
  bool vsync = true;
  std::string screenshot;              // PNG of the last frame, if set
  bool quitAtEnd = false;              // close when the scenario's duration is reached
};

// Runs until the person quits, the time limit, or (quitAtEnd) the scenario
// ends. Returns the loop statistics. Throws render::RenderError when no
// window can be opened (the caller falls back to headless).
LoopStats runInteractive(DriveSession& session, const InteractiveOptions& options);

}  // namespace bdfcar::app
