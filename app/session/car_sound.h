// What the car sounds like now (audio/sound_state.h), from a drive: the
// engine's speed and load (a car without a powertrain, the reference sedan,
// gets a notional engine geared to its speed so that it is not silent), the
// tyres' combined slips and loads, the speed, a shift under way, and the
// suspension's hits (the largest wheel travel rate since the last tick).
#pragma once

#include <array>

#include "audio/sound_state.h"
#include "session/drive_session.h"

namespace bdfcar::app {

class CarSound {
 public:
  // The state after the session's last tick (a rewind or a reset is no hit).
  audio::SoundState update(const DriveSession& session);

 private:
  std::array<double, 4> travel_{};
  double time_ = -1e300;
};

}  // namespace bdfcar::app
