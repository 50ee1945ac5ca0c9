// A run state (simulation.h's RunState) as a flat, versioned run of bytes:
// what a caller stores, hashes, sends to another process or hands to Python
// as `bytes`, and restores from. Every field of the state, in a fixed order;
// numbers as the machine holds them (IEEE doubles, little-endian on every
// platform bdfcar builds for), so a state read back is the state written,
// bit for bit, and a run continued from it steps as the original does.
//
// Layout: "BDFCARRS", the format version (uint32), the payload's length
// (uint64), the payload, the payload's FNV-1a 64 hash. A state of another
// format version, a truncated or corrupted one, or one with bytes left over
// is refused with a RunStateBytesError saying which; whether the state fits
// a simulation (its models' fingerprint, rung and sizes) is
// Simulation::restoreBytes' check.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenario/simulation.h"

namespace bdfcar::scenario {

// 2: the model fingerprint (RunState::model) first. 3: the latest
// evaluation's tyre outputs left out (they are not state), the accepted
// step's tyre force in. 5: the integrator's steps since its Jacobian left
// out (the Jacobian's age, not state: a restored run evaluates a fresh one).
inline constexpr std::uint32_t kRunStateFormat = 7;

class RunStateBytesError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

std::vector<char> runStateToBytes(const RunState& s);
// Throws RunStateBytesError naming what is wrong and where.
RunState runStateFromBytes(const std::vector<char>& bytes);
// FNV-1a 64 of the state's bytes: equal states, equal hashes.
std::uint64_t hashRunState(const RunState& s);

}  // namespace bdfcar::scenario
