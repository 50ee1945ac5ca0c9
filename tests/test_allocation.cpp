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

TEST(RealTime, BdfStepAllocatesNothingAfterTheFirstStep) {
  const mb::Model m = test::paperTopology();
  mb::MultibodyDae dae(m);
  integ::BdfOptions o;
  o.order = 2;
  o.newtonIterations = 2;
  o.atol = 1e-8;
  o.jacobianEvery = 5;  // Jacobian refreshes and refactorizations happen inside the counted window
  integ::BdfIntegrator bdf(dae, o);
  integ::Vec q = mb::neutralPositions(m), v = integ::Vec::Zero(m.nv);
  v(0) = 10.0;
  integ::Message msg;
  ASSERT_EQ(bdf.initialize(0, q, v, msg), integ::EvalStatus::Ok);
  ASSERT_TRUE(bdf.step(0.01).ok());
  const long jacobiansBefore = bdf.counters().jacobians;
  const long before = gAllocations.load();
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(bdf.step(0.01).ok());
  const long during = gAllocations.load() - before;
  EXPECT_EQ(during, 0) << "heap allocations in 50 steps";
  EXPECT_GE(bdf.counters().jacobians - jacobiansBefore, 9) << "the window must include Jacobian refreshes";
  // The counter itself works: an allocation is seen.
  auto* probe = new int(3);
  EXPECT_EQ(gAllocations.load() - before, 1);
  delete probe;
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
