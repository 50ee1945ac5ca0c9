// Force feedback as numbers: the caller's steering torque command -> the
// level of SDL's constant-force effect.
#pragma once

#include "input/mapping.h"

namespace bdfcar::input {

inline constexpr int kForceFeedbackFullLevel = 32767;

// Constant-force level in [-32767, 32767] for a torque command in [-1, 1]
// (+ = turns the wheel to the left): command * gain, clamped, sign flipped if
// `invert`; 0 when force feedback is disabled or the command is not finite.
int forceFeedbackLevel(const ForceFeedbackMapping& mapping, double command);

}  // namespace bdfcar::input
