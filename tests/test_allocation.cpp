// Real-time discipline: after the first step a BDF step allocates no heap
// memory, Jacobian refreshes included. Counted by replacing the global
// operator new for this test executable only.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "integrator/bdf.h"
#include "mechanisms.h"
#include "multibody/multibody_dae.h"
#include "saturating_wheel.h"

namespace {
std::atomic<long> gAllocations{0};
}

void* operator new(std::size_t n) {
  ++gAllocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, std::align_val_t al) {
  ++gAllocations;
  const std::size_t a = static_cast<std::size_t>(al);
  if (void* p = std::aligned_alloc(a, (n + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n, std::align_val_t al) { return operator new(n, al); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

using namespace bdfcar;

namespace {

// The paper's closed loop moving at 10 m/s under options o: after its first
// step, what `steps` more allocate and evaluate.
struct CountedSteps {
  long allocations = 0, jacobians = 0, jacobianResiduals = 0;
  int nv = 0;
};
CountedSteps countSteps(integ::BdfOptions o, int steps) {
  const mb::Model m = test::paperTopology();
  mb::MultibodyDae dae(m);
  o.order = 2;
  o.newtonIterations = 2;
  o.atol = 1e-8;
  integ::BdfIntegrator bdf(dae, o);
  integ::Vec q = mb::neutralPositions(m), v = integ::Vec::Zero(m.nv);
  v(0) = 10.0;
  integ::Message msg;
  CountedSteps c;
  c.nv = m.nv;
  EXPECT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  EXPECT_TRUE(bdf.step(0.01).ok());
  const integ::Counters before = bdf.counters();
  const long allocationsBefore = gAllocations.load();
  for (int i = 0; i < steps; ++i) EXPECT_TRUE(bdf.step(0.01).ok());
  c.allocations = gAllocations.load() - allocationsBefore;
  c.jacobians = bdf.counters().jacobians - before.jacobians;
  c.jacobianResiduals = bdf.counters().jacobianResiduals - before.jacobianResiduals;
  return c;
}

}  // namespace

TEST(RealTime, BdfStepAllocatesNothingAfterTheFirstStep) {
  integ::BdfOptions o;
  o.jacobianEvery = 5;  // Jacobian refreshes and refactorizations happen inside the counted window
  const CountedSteps c = countSteps(o, 50);
  EXPECT_EQ(c.allocations, 0) << "heap allocations in 50 steps";
  EXPECT_GE(c.jacobians, 9) << "the window must include Jacobian refreshes";
  // The counter itself works: an allocation is seen.
  const long before = gAllocations.load();
  auto* probe = new int(3);
  EXPECT_EQ(gAllocations.load() - before, 1);
  delete probe;
}

TEST(RealTime, BdfStepAllocatesNothingTakingAJacobianInSlices) {
  // The default policy's periodic Jacobian, one slice of its columns a step
  // (BdfOptions::jacobianSlices), whole inside the counted window.
  integ::BdfOptions o;
  o.jacobianEvery = 40;
  o.jacobianSlices = 4;
  const CountedSteps c = countSteps(o, 90);
  EXPECT_EQ(c.allocations, 0) << "heap allocations in 90 steps";
  EXPECT_EQ(c.jacobians, 2) << "the window must include two Jacobians in slices";
  // Each in four slices: a residual more per slice than the whole's 2 nv + 1.
  EXPECT_EQ(c.jacobianResiduals, 2 * (2 * c.nv + 4));
}

TEST(RealTime, BdfStepRescuesAllocateNothing) {
  // Stalled steps: fast-column refreshes, LU-only solves and damped Newton
  // (the rough road's path) inside the counted window.
  test::SaturatingWheel dae({1}, 0.4);
  integ::BdfIntegrator bdf(dae, integ::BdfOptions{});
  integ::Vec q = integ::Vec::Zero(3), v(3);
  v << 15.0, 15.0 / test::SaturatingWheel::kR, 0.0;
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  ASSERT_TRUE(bdf.step(0.01).ok());
  const integ::Counters c0 = bdf.counters();
  const long before = gAllocations.load();
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(bdf.step(0.01).ok());
  EXPECT_EQ(gAllocations.load() - before, 0) << "heap allocations in 50 steps";
  EXPECT_GE(bdf.counters().columnRefreshes - c0.columnRefreshes, 10) << "the window must include rescues";
  EXPECT_GE(bdf.counters().rescues - c0.rescues, 3);
}
