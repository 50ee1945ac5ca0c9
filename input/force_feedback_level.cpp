#include <algorithm>
#include <cmath>

#include "input/force_feedback.h"

namespace bdfcar::input {

// SDL constant-force level for a steering torque command (see the header).
int forceFeedbackLevel(const ForceFeedbackMapping& m, double command) {
  if (!m.enabled || !std::isfinite(command)) return 0;
  double level = std::clamp(command * m.gain, -1.0, 1.0);
  if (m.invert) level = -level;
  return static_cast<int>(std::lround(level * kForceFeedbackFullLevel));
}

}  // namespace bdfcar::input
