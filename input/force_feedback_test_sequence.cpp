// The force-feedback test's pushes as numbers (force_feedback.h).
#include "input/force_feedback.h"

namespace bdfcar::input {

// Eased in over 0.3 s, held 1 s, eased out over 0.3 s; left, then right.
const std::vector<ForceFeedbackTestPhase>& forceFeedbackTestPhases() {
  constexpr double c = kForceFeedbackTestCommand;
  static const std::vector<ForceFeedbackTestPhase> phases = {
      {"easing into a push to the left", 0.3, 0.0, c},
      {"pushing left: the wheel should turn to the left", 1.0, c, c},
      {"easing off", 0.3, c, 0.0},
      {"easing into a push to the right", 0.3, 0.0, -c},
      {"pushing right: the wheel should turn to the right", 1.0, -c, -c},
      {"easing off", 0.3, -c, 0.0},
  };
  return phases;
}

// The phase whose interval [start, start + seconds) holds t.
int forceFeedbackTestPhase(double t) {
  if (!(t >= 0.0)) return -1;
  const std::vector<ForceFeedbackTestPhase>& phases = forceFeedbackTestPhases();
  double start = 0.0;
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (t < start + phases[i].seconds) return static_cast<int>(i);
    start += phases[i].seconds;
  }
  return -1;
}

// Linear within the phase holding t.
double forceFeedbackTestCommand(double t) {
  const int i = forceFeedbackTestPhase(t);
  if (i < 0) return 0.0;
  const std::vector<ForceFeedbackTestPhase>& phases = forceFeedbackTestPhases();
  double start = 0.0;
  for (int k = 0; k < i; ++k) start += phases[k].seconds;
  const ForceFeedbackTestPhase& p = phases[i];
  return p.from + (p.to - p.from) * (t - start) / p.seconds;
}

}  // namespace bdfcar::input
