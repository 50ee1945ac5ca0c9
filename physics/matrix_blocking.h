// Eigen blocks its matrix products, and the LU factorisations and triangular
// solves built on them, by the CPU's cache sizes, which it reads at run time:
// the order of the sums, and so the last bits of a product of a few dozen
// rows, follows the machine. The sedan's J-turn gave other telemetry on a
// machine with a 48 KiB L1 data cache than on one with 32 KiB, same build.
// The determinism contract (docs/DESIGN.md) wants the same bits on any
// machine of a build flavour, so the sizes Eigen blocks by are pinned to one
// set: every path that builds a model or an integrator calls this first
// (cheap: three loads when already pinned). The values are those of the
// machine the golden runs were recorded on, so the golden hashes stand; on
// matrices of a few dozen rows the blocking decides the sums' order, not
// the speed.
#pragma once

#include <Eigen/Core>

namespace bdfcar {

inline constexpr std::ptrdiff_t kPinnedL1 = 32 * 1024, kPinnedL2 = 1024 * 1024, kPinnedL3 = 32 * 1024 * 1024;

inline void pinMatrixBlocking() {
  if (Eigen::l1CacheSize() != kPinnedL1 || Eigen::l2CacheSize() != kPinnedL2 || Eigen::l3CacheSize() != kPinnedL3)
    Eigen::setCpuCacheSizes(kPinnedL1, kPinnedL2, kPinnedL3);
}

}  // namespace bdfcar
