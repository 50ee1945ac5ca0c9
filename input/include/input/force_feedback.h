// Force feedback as numbers: the caller's steering torque command -> the
// level of SDL's constant-force effect.
#pragma once

#include <vector>

#include "input/mapping.h"

namespace bdfcar::input {

inline constexpr int kForceFeedbackFullLevel = 32767;

// Constant-force level in [-32767, 32767] for a torque command in [-1, 1]
// (+ = turns the wheel to the left): command * gain, clamped, sign flipped if
// `invert`; 0 when force feedback is disabled or the command is not finite.
int forceFeedbackLevel(const ForceFeedbackMapping& mapping, double command);

// `bdfcar input --ffb-test`: a gentle push to the left, then one to the
// right, as phases of steering torque commands (+ = left, as
// InputSystem::setSteeringTorque takes them; the mapping's gain and invert
// apply as when driving), each ramping linearly from `from` to `to`: eased in
// and out, never a jolt.
struct ForceFeedbackTestPhase {
  const char* what;  // what the person should feel, printed as the phase begins
  double seconds;
  double from, to;
};

// The largest command of the test: a quarter of the torque at which driving feels full.
inline constexpr double kForceFeedbackTestCommand = 0.25;

// The phases, in order.
const std::vector<ForceFeedbackTestPhase>& forceFeedbackTestPhases();

// The phase running at t seconds since the start, or -1 before and after the test.
int forceFeedbackTestPhase(double t);

// The command at t seconds since the start; 0 before and after the test.
double forceFeedbackTestCommand(double t);

}  // namespace bdfcar::input
